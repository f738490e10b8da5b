# spancast as others install and use it: `cmake --install` of the build
# tree into a scratch prefix, then from there
#   - the installed tool (its version, the OpenImageIO plugin and
#     spancast-bench found in LIBDIR/spancast);
#   - the public headers compiled as C and as C++ with -Wall -Wextra
#     -pedantic -Werror, and the version macros against sc_version(),
#     pkg-config and `spancast --version`;
#   - the examples, copied out of the installed documentation and built
#     against the installed library with pkg-config and with CMake's
#     find_package(spancast), run and checked against the tool;
#   - libspancast.so's dynamic symbols: exactly the functions the headers
#     declare, all sc_*;
#   - the man pages: they render without warnings, and each command's page
#     documents every option its --help lists;
#   - the bash completion: commands, options and model files;
#   - the Debian package (cpack -G DEB): its files, its dependencies, and
#     the tool and library unpacked with dpkg-deb -x and run from there.
# Nothing is rebuilt: the install copies the build tree's files.
#
# Run as: bash cli_install.sh <path-to-spancast> <source-dir> <work-dir>
. "$(dirname "$0")/testlib.sh"
require_tools cmake pkg-config cc c++ nm readelf ldd man cpack dpkg-deb dpkg-shlibdeps file python3

build=$(dirname "$bin")
[ -f "$build/CMakeCache.txt" ] || skip "no CMake build tree beside $bin"
prefix=$work/prefix

# A build with the sanitizers (SPANCAST_SANITIZE) makes a library that
# needs their runtime loaded first: programs linking it are built with
# them too.
san_flags=()
if nm -D "$build/libspancast.so" | grep -q ' U __asan_init'; then
    san_flags=(-fsanitize=address,undefined -fno-omit-frame-pointer)
fi

# A 10 mm cube drilled along z through (5, 5) with radius 2.
cat >drilled.csg <<'CSG'
difference() {
  cube(size = [10, 10, 10], center = false);
  multmatrix([[1, 0, 0, 5], [0, 1, 0, 5], [0, 0, 1, -1], [0, 0, 0, 1]]) {
    cylinder(h = 12, r1 = 2, r2 = 2, center = false);
  }
}
CSG

# loaded LD_DEBUG_FILE NAME: the real path of every file NAME that ld.so's
# LD_DEBUG=files log says was loaded.
loaded() {
    sed -n "s/^ *[0-9]*:[[:space:]]*file=\([^ ]*$2\) .*/\1/p" "$1" | sort -u |
        while read -r f; do realpath "$f"; done
}

# ---- cmake --install ----
check
if ! cmake --install "$build" --prefix "$prefix" >install.log 2>&1; then
    cat install.log
    fail "cmake --install"
    exit 1
fi
pcdir=$(dirname "$(ls "$prefix"/lib*/pkgconfig/spancast.pc "$prefix"/lib/*/pkgconfig/spancast.pc 2>/dev/null | head -n 1)")
libdir=$(dirname "$pcdir")
version=$(PKG_CONFIG_PATH=$pcdir pkg-config --modversion spancast)
for f in bin/spancast include/spancast/spancast.h include/spancast/version.h \
    share/man/man1/spancast.1 share/man/man1/spancast-render.1 share/man/man3/libspancast.3 \
    share/bash-completion/completions/spancast share/doc/spancast/README.md \
    share/doc/spancast/examples/CMakeLists.txt; do
    check
    [ -f "$prefix/$f" ] || fail "not installed: $f"
done
for f in libspancast.so spancast/spancast-oiio.so spancast/spancast-bench spancast/spancast-view \
    cmake/spancast/spancastConfig.cmake cmake/spancast/spancastConfigVersion.cmake \
    cmake/spancast/spancastTargets.cmake; do
    check
    [ -e "$libdir/$f" ] || fail "not installed: $libdir/$f"
done
# The soname carries the project version (MAJOR.MINOR while MAJOR is 0).
major=${version%%.*}
minor=${version#*.}
minor=${minor%%.*}
if [ "$major" = 0 ]; then soversion=0.$minor; else soversion=$major; fi
check
soname=$(readelf -d "$libdir/libspancast.so" | sed -n 's/.*Library soname: \[\(.*\)\]/\1/p')
[ "$soname" = "libspancast.so.$soversion" ] ||
    fail "soname '$soname', want libspancast.so.$soversion"
check
[ -f "$libdir/libspancast.so.$version" ] || fail "no libspancast.so.$version"

# ---- the installed tool ----
check
out=$("$prefix/bin/spancast" --version)
[ "$out" = "spancast $version" ] || fail "installed spancast --version: '$out', want 'spancast $version'"
# A TIFF goes through the OpenImageIO plugin: the installed one, not the
# build tree's (ld.so names every file it loads).
check
if LD_DEBUG=files "$prefix/bin/spancast" render drilled.csg -o drilled.tif --imgsize=64,48 -q \
    2>ld-tool.txt; then
    got=$(loaded ld-tool.txt spancast-oiio.so)
    [ "$got" = "$(realpath "$libdir/spancast/spancast-oiio.so")" ] ||
        fail "the installed tool loaded '$got', not $libdir/spancast/spancast-oiio.so"
    [ -s drilled.tif ] || fail "installed spancast wrote no drilled.tif"
else
    fail "installed spancast render to .tif: $(grep -v '^ *[0-9]*:' ld-tool.txt)"
fi
# `spancast bench` starts the installed spancast-bench: its own message for
# a bad option (exit 2), not "cannot find spancast-bench" (exit 1).
check
"$prefix/bin/spancast" bench accuracy --no-such-option >bench.out 2>bench.err
rc=$?
[ "$rc" = 2 ] && grep -q "unknown option '--no-such-option'" bench.err ||
    fail "installed spancast bench: exit $rc, '$(cat bench.err)'"
# `spancast view` starts the installed spancast-view the same way: its own
# message for a bad option, not "cannot find spancast-view".
check
"$prefix/bin/spancast" view --no-such-option >view.out 2>view.err
rc=$?
[ "$rc" = 2 ] && grep -q "unknown option '--no-such-option'" view.err ||
    fail "installed spancast view: exit $rc, '$(cat view.err)'"

# ---- the headers as C and C++, and the version ----
# Every installed header, then a program printing the version three ways.
for h in "$prefix"/include/spancast/*.h; do
    echo "#include <spancast/$(basename "$h")>"
done >version.c
cat >>version.c <<'C'
#include <spancast/spancast.h>
#include <stdio.h>
#include <string.h>
#if SPANCAST_VERSION_NUMBER != SPANCAST_VERSION_MAJOR * 10000 + SPANCAST_VERSION_MINOR * 100 + SPANCAST_VERSION_PATCH
#error SPANCAST_VERSION_NUMBER does not agree with its parts
#endif
int main(void)
{
    char parts[64];
    snprintf(parts, sizeof parts, "%d.%d.%d", SPANCAST_VERSION_MAJOR, SPANCAST_VERSION_MINOR,
             SPANCAST_VERSION_PATCH);
    printf("%s %s %s\n", SPANCAST_VERSION_STRING, parts, sc_version());
    return strcmp(parts, SPANCAST_VERSION_STRING) != 0;
}
C
cp version.c version.cpp
export PKG_CONFIG_PATH=$pcdir
read -r -a pc_flags <<<"$(pkg-config --cflags --libs spancast)"
check
if cc -std=c11 -Wall -Wextra -pedantic -Werror "${san_flags[@]}" version.c "${pc_flags[@]}" \
    -o version_c 2>cc.txt; then
    out=$(LD_LIBRARY_PATH=$libdir ./version_c)
    [ "$out" = "$version $version $version" ] ||
        fail "version macros and sc_version(): '$out', want '$version' three times"
else
    fail "the header does not compile as C: $(cat cc.txt)"
fi
check
if c++ -std=c++11 -Wall -Wextra -pedantic -Werror "${san_flags[@]}" version.cpp \
    "${pc_flags[@]}" -o version_cpp 2>cxx.txt; then
    out=$(LD_LIBRARY_PATH=$libdir ./version_cpp)
    [ "$out" = "$version $version $version" ] || fail "C++: '$out'"
else
    fail "the header does not compile as C++: $(cat cxx.txt)"
fi

# ---- the examples against the installed library ----
# The reference: what the tool says about the same ray.
"$bin" spans drilled.csg --ray=-1,5,5,2,0,0 --json >tool-spans.json || fail "spancast spans"
want_t=$(python3 -c "import json,sys
j = json.load(open(sys.argv[1]))
print(' '.join('%r %r' % (s['in']['t'], s['out']['t']) for s in j['rays'][0]['spans']))" \
    tool-spans.json)

# check_examples DIR HOW: runs the two examples built in DIR.
check_examples() {
    local dir=$1 how=$2
    check
    local lib
    lib=$(LD_LIBRARY_PATH=$libdir ldd "$dir/spans_ray" | awk '/libspancast/ { print $3 }')
    [ "$lib" = "$libdir/libspancast.so.$soversion" ] ||
        fail "$how: spans_ray links '$lib', want $libdir/libspancast.so.$soversion"
    check
    if LD_LIBRARY_PATH=$libdir "$dir/spans_ray" drilled.csg -1 5 5 2 0 0 >"$dir/spans.txt"; then
        local got
        got=$(sed -n 's/^  \(in \|out\) t=\([^ ]*\) .*/\2/p' "$dir/spans.txt" | tr '\n' ' ')
        [ "$(head -n 1 "$dir/spans.txt")" = "2 spans" ] ||
            fail "$how: spans_ray: '$(head -n 1 "$dir/spans.txt")', want '2 spans'"
        python3 - "$got" "$want_t" <<'PY' || fail "$how: spans_ray t '$got', the tool's '$want_t'"
import sys
got = [float(x) for x in sys.argv[1].split()]
want = [float(x) for x in sys.argv[2].split()]
assert got == want and got == [0.5, 2.0, 4.0, 5.5], (got, want)
PY
    else
        fail "$how: spans_ray failed"
    fi
    check
    if LD_DEBUG=files LD_LIBRARY_PATH=$libdir "$dir/render_buffer" drilled.csg "$dir/drilled.tif" \
        >"$dir/render.txt" 2>"$dir/ld.txt"; then
        grep -q "^libspancast $version (header $version)$" "$dir/render.txt" ||
            fail "$how: render_buffer version line: $(head -n 1 "$dir/render.txt")"
        grep -q "^centre hit$" "$dir/render.txt" || fail "$how: render_buffer: centre not hit"
        local hits total
        read -r hits total < <(sed -n 's/^hit pixels \([0-9]*\) of \([0-9]*\)$/\1 \2/p' "$dir/render.txt")
        [ -n "$hits" ] && [ "$hits" -gt 0 ] && [ "$hits" -lt "$total" ] ||
            fail "$how: render_buffer hit '$hits' of '$total' pixels"
        [ -s "$dir/drilled.tif" ] || fail "$how: render_buffer wrote no TIFF"
        # The shared library finds its plugin in LIBDIR/spancast.
        local got_plugin
        got_plugin=$(loaded "$dir/ld.txt" spancast-oiio.so)
        [ "$got_plugin" = "$(realpath "$libdir/spancast/spancast-oiio.so")" ] ||
            fail "$how: libspancast loaded '$got_plugin', not $libdir/spancast/spancast-oiio.so"
    else
        fail "$how: render_buffer failed: $(grep -v '^ *[0-9]*:' "$dir/ld.txt")"
    fi
}

examples=$prefix/share/doc/spancast/examples
mkdir -p ex-pkgconfig
check
if cc -std=c11 -Wall -Wextra -Werror "${san_flags[@]}" "$examples/spans_ray.c" "${pc_flags[@]}" \
    -o ex-pkgconfig/spans_ray 2>cc.txt &&
    cc -std=c11 -Wall -Wextra -Werror "${san_flags[@]}" "$examples/render_buffer.c" \
        "${pc_flags[@]}" -o ex-pkgconfig/render_buffer 2>>cc.txt; then
    check_examples ex-pkgconfig pkg-config
else
    fail "examples with pkg-config: $(cat cc.txt)"
fi
check
san_cmake=()
if [ ${#san_flags[@]} != 0 ]; then
    san_cmake=("-DCMAKE_C_FLAGS=${san_flags[*]}" "-DCMAKE_EXE_LINKER_FLAGS=${san_flags[*]}")
fi
if env -u PKG_CONFIG_PATH cmake -S "$examples" -B ex-cmake -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_BUILD_TYPE=Release "${san_cmake[@]}" >cmake.txt 2>&1 &&
    cmake --build ex-cmake >>cmake.txt 2>&1; then
    check_examples ex-cmake find_package
else
    cat cmake.txt
    fail "examples with find_package(spancast)"
fi

# ---- exported symbols ----
# Exactly the functions the public headers declare (comments dropped by the
# preprocessor), all sc_*; the version script makes everything else local.
check
nm -D --defined-only "$libdir/libspancast.so" | awk '{ print $NF }' | sort >exported.txt
for h in "$prefix"/include/spancast/*.h; do
    echo "#include <spancast/$(basename "$h")>"
done | cc -E -P -I"$prefix/include" - |
    grep -o '\bsc_[a-z0-9_]*[[:space:]]*(' | tr -d ' (' | sort -u >declared.txt
if ! diff declared.txt exported.txt >symbols.diff; then
    fail "dynamic symbols of libspancast.so (<: declared, not exported; >: exported, not declared):
$(cat symbols.diff)"
fi
check
[ "$(grep -c . exported.txt)" -gt 20 ] || fail "only $(grep -c . exported.txt) symbols exported"

# ---- man pages ----
export MANWIDTH=2000 LC_ALL=C
for page in "$prefix"/share/man/man1/*.1 "$prefix"/share/man/man3/*.3; do
    check
    man --warnings -l "$page" >"$(basename "$page").txt" 2>man-err.txt || fail "man -l $page"
    [ ! -s man-err.txt ] || fail "man -l $(basename "$page"): $(cat man-err.txt)"
done
check
MANPATH=$prefix/share/man man -w spancast-render >/dev/null 2>&1 ||
    fail "man -w spancast-render with MANPATH=$prefix/share/man"
# The options of each command (parsed from its --help as the completion
# does) against its page; --help and --version against spancast(1).
. "$prefix/share/bash-completion/completions/spancast"
commands=$(_spancast_commands "$bin")
check
[ "$(echo "$commands" | tr '\n' ' ')" != "" ] || fail "no commands parsed from --help"
for command in $commands; do
    page=spancast-$command.1
    check
    if [ ! -f "$page.txt" ]; then
        fail "no man page $page for the command '$command' of --help"
        continue
    fi
    grep -q "spancast-$command" spancast.1.txt || fail "spancast(1) does not name spancast-$command"
    options=$(_spancast_command_options "$bin" "$command")
    for option in $options; do
        check
        # The option as a word of the page: "-o" not inside "--output".
        grep -Eq -- "(^|[^A-Za-z0-9_-])$option([^A-Za-z0-9_-]|$)" "$page.txt" ||
            fail "$page does not document $option (spancast $command --help lists it)"
    done
done
# Options parsed for the commands that have some, so that the parse
# above cannot pass by finding nothing.
for want in render:--imgsize render:-o spans:--ray inside:--point bench:--csv; do
    check
    _spancast_command_options "$bin" "${want%%:*}" | grep -qx -- "${want#*:}" ||
        fail "--help parse: ${want#*:} not found for ${want%%:*}"
done
for option in --help -h --version; do
    check
    grep -Eq -- "(^|[^A-Za-z0-9_-])$option([^A-Za-z0-9_-]|$)" spancast.1.txt ||
        fail "spancast.1 does not document $option"
done
unset LC_ALL MANWIDTH

# ---- bash completion ----
# complete_words WORD...: what the completion offers for the command line
# "spancast WORD..." with the cursor at the end of the last word.
complete_words() {
    COMP_WORDS=(spancast "$@")
    COMP_CWORD=$#
    COMPREPLY=()
    _spancast "$bin" "${COMP_WORDS[COMP_CWORD]}" "${COMP_WORDS[COMP_CWORD - 1]}"
    printf '%s\n' "${COMPREPLY[@]}" | sort
}
for command in $commands; do
    check
    complete_words "" | grep -qx "$command" || fail "completion: command $command not offered"
    for option in $(_spancast_command_options "$bin" "$command"); do
        check
        complete_words "$command" "${option:0:2}" | grep -qx -- "$option" ||
            fail "completion: spancast $command ${option:0:2}<TAB> does not offer $option"
    done
done
mkdir -p models/sub
touch models/a.csg models/b.scad models/c.stl models/d.off models/e.txt models/f.png
check
got=$(complete_words render models/ | tr '\n' ' ')
[ "$got" = "models/a.csg models/b.scad models/c.stl models/d.off models/sub " ] ||
    fail "completion of a model file: '$got'"
check
got=$(complete_words render drilled.csg -o models/f | tr '\n' ' ')
[ "$got" = "models/f.png " ] || fail "completion of -o FILE: '$got'"
# "--mask=" is three words to bash ('=' breaks words): the value is a file.
check
got=$(complete_words render drilled.csg --mask = models/e | tr '\n' ' ')
[ "$got" = "models/e.txt " ] || fail "completion of --mask=FILE: '$got'"
check
got=$(cd models && complete_words render drilled.csg --mask = | tr '\n' ' ')
[ "$got" = "a.csg b.scad c.stl d.off e.txt f.png sub " ] || fail "completion of --mask=: '$got'"

# ---- the Debian package ----
check
if ! cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work/deb" >cpack.txt 2>&1; then
    cat cpack.txt
    fail "cpack -G DEB"
    echo "$checks checks, $fails failures"
    exit 1
fi
deb=$(ls "$work"/deb/*.deb)
check
dpkg-deb -f "$deb" Package Version Depends Recommends Suggests >control.txt
grep -qx "Package: spancast" control.txt || fail "deb: $(cat control.txt)"
grep -qx "Version: $version" control.txt || fail "deb version: $(cat control.txt)"
depends=$(sed -n 's/^Depends: //p' control.txt)
recommends=$(sed -n 's/^Recommends: //p' control.txt)
# What is linked: from dpkg-shlibdeps (libc6, libpng16-16, the OpenEXR and
# text libraries, libgomp1); OpenImageIO only recommended, since only the
# plugin loaded on demand links it.
for pkg in libc6 libpng16-16 libgomp1 libfreetype6 libharfbuzz0b libfontconfig1 libpolyclipping22; do
    check
    echo "$depends" | grep -Eq "(^|, )$pkg( |,|$)" || fail "deb Depends lacks $pkg: $depends"
done
check
echo "$depends" | grep -q openimageio && fail "deb Depends on OpenImageIO: $depends"
for pkg in openscad libopenimageio2.4 libsdl2-2.0-0 libopenmpi3 ffmpeg; do
    check
    echo "$recommends" | grep -Eq "(^|, )$pkg( |,|$)" || fail "deb Recommends lacks $pkg: $recommends"
done
# Every Depends is a package installed here (the build linked it); every
# Recommends one that apt knows, where apt has package lists at all.
names() { tr ',' '\n' | sed 's/(.*//; s/|.*//' | tr -d ' '; }
for pkg in $(echo "$depends" | names); do
    check
    dpkg-query -W "$pkg" >/dev/null 2>&1 || fail "deb Depends on $pkg, which is not installed"
done
if apt-cache show libc6 >/dev/null 2>&1; then
    read -r -a recommended < <(echo "$recommends" | names | tr '\n' ' ')
    apt-cache show --no-all-versions "${recommended[@]}" 2>/dev/null |
        sed -n 's/^Package: //p' | sort -u >known.txt
    for pkg in "${recommended[@]}"; do
        check
        grep -qx "$pkg" known.txt || fail "deb Recommends $pkg, which apt does not know"
    done
fi
# The shared library is registered: a shlibs entry for packages that link
# it, and ldconfig after install.
check
dpkg-deb --ctrl-tarfile "$deb" | tar -xO ./shlibs 2>/dev/null |
    grep -q "^libspancast $soversion spancast (>= $version)$" || fail "deb: no shlibs entry"
check
dpkg-deb --ctrl-tarfile "$deb" | tar -xO ./postinst 2>/dev/null | grep -q ldconfig ||
    fail "deb: postinst does not run ldconfig"
# Unpacked anywhere, the tool and the library work from there.
root=$work/root
dpkg-deb -x "$deb" "$root"
check
[ -x "$root/usr/bin/spancast" ] || fail "deb lacks usr/bin/spancast"
debpc=$(dirname "$(ls "$root"/usr/lib/pkgconfig/spancast.pc "$root"/usr/lib/*/pkgconfig/spancast.pc 2>/dev/null | head -n 1)")
deblib=$(dirname "$debpc")
check
out=$("$root/usr/bin/spancast" --version)
[ "$out" = "spancast $version" ] || fail "unpacked spancast --version: '$out'"
check
if LD_DEBUG=files "$root/usr/bin/spancast" render drilled.csg -o deb.tif --imgsize=64,48 -q \
    2>ld-deb.txt; then
    got=$(loaded ld-deb.txt spancast-oiio.so)
    [ "$got" = "$(realpath "$deblib/spancast/spancast-oiio.so")" ] ||
        fail "the unpacked tool loaded '$got', not its own plugin"
else
    fail "unpacked spancast render: $(grep -v '^ *[0-9]*:' ld-deb.txt)"
fi
check
mkdir -p ex-deb
if PKG_CONFIG_PATH=$debpc cc -std=c11 "${san_flags[@]}" "$root/usr/share/doc/spancast/examples/spans_ray.c" \
    $(PKG_CONFIG_PATH=$debpc pkg-config --cflags --libs spancast) -o ex-deb/spans_ray 2>cc.txt; then
    out=$(LD_LIBRARY_PATH=$deblib ex-deb/spans_ray drilled.csg -1 5 5 2 0 0 | head -n 1)
    [ "$out" = "2 spans" ] || fail "spans_ray against the unpacked library: '$out'"
    check
    lib=$(LD_LIBRARY_PATH=$deblib ldd ex-deb/spans_ray | awk '/libspancast/ { print $3 }')
    [ "$lib" = "$deblib/libspancast.so.$soversion" ] || fail "ex-deb/spans_ray links '$lib'"
else
    fail "example against the unpacked .deb: $(cat cc.txt)"
fi

echo "$checks checks, $fails failures"
[ "$fails" = 0 ]
