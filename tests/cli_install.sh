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
#   - the Debian packages (cpack -G DEB), split as Debian splits a library:
#     libspancastN (the shared library), libspancast-dev and spancast (the
#     tool): each one's files (dpkg-deb -c), its DEP-5 copyright file, its
#     dependencies; then all three installed with dpkg into a scratch root
#     without root rights (dpkg --force-not-root --root, against a copy of
#     this system's package database, so their Depends are checked), and
#     the tool and library run from there.
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
    share/doc/spancast/copyright share/doc/libspancast-dev/examples/CMakeLists.txt; do
    check
    [ -f "$prefix/$f" ] || fail "not installed: $f"
done
for f in libspancast.so spancast/spancast-oiio.so spancast/spancast-tiff.so spancast/spancast-cgal.so spancast/spancast-xml.so spancast/spancast-3mf.so spancast/spancast-text.so spancast/spancast-exr.so spancast/spancast-bench spancast/spancast-view \
    cmake/spancast/spancastConfig.cmake cmake/spancast/spancastConfigVersion.cmake \
    cmake/spancast/spancastTargets.cmake; do
    check
    [ -e "$libdir/$f" ] || fail "not installed: $libdir/$f"
done
# The soname's number is the one the ABI record names (abi/README.md).
soversion=$(sed -n "1s/.*soname='libspancast\.so\.\([0-9]*\)'.*/\1/p" "$src/abi/libspancast.abi")
check
soname=$(readelf -d "$libdir/libspancast.so" | sed -n 's/.*Library soname: \[\(.*\)\]/\1/p')
[ "$soname" = "libspancast.so.$soversion" ] ||
    fail "soname '$soname', want libspancast.so.$soversion"
check
[ -f "$libdir/libspancast.so.$version" ] || fail "no libspancast.so.$version"

# ---- the installed tool ----
check
out=$("$prefix/bin/spancast" --version | head -n 1)
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
# text() and EXR go through their plugins: the installed ones.
cat >hello.csg <<'CSG'
linear_extrude(height = 2) { text(text = "Hi", size = 10); }
CSG
for plugin in text exr; do
    check
    model=drilled.csg
    [ "$plugin" = text ] && model=hello.csg
    if LD_DEBUG=files "$prefix/bin/spancast" render "$model" -o "$plugin.exr" --imgsize=64,48 \
        -q 2>ld-$plugin.txt; then
        got=$(loaded ld-$plugin.txt spancast-$plugin.so)
        [ "$got" = "$(realpath "$libdir/spancast/spancast-$plugin.so")" ] ||
            fail "the installed tool loaded '$got', not $libdir/spancast/spancast-$plugin.so"
        [ -s "$plugin.exr" ] || fail "installed spancast wrote no $plugin.exr"
    else
        fail "installed spancast render of $model to .exr: $(grep -v '^ *[0-9]*:' ld-$plugin.txt)"
    fi
done
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

# Under mpirun, the installed tool hands render over to the installed
# spancast-mpi (when the build has one: Open MPI was found).
if [ -x "$(dirname "$bin")/spancast-mpi" ]; then
    check
    [ -x "$libdir/spancast/spancast-mpi" ] || fail "not installed: $libdir/spancast/spancast-mpi"
    if command -v mpirun >/dev/null; then
        check
        mpirun_test -np 2 "$prefix/bin/spancast" render drilled.csg \
            -o drilled-mpi.png --imgsize=64,48 -q >mpi.out 2>&1 ||
            fail "installed spancast under mpirun: $(tail -n 3 mpi.out)"
        [ -s drilled-mpi.png ] || fail "installed spancast under mpirun wrote no PNG"
    fi
fi

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

examples=$prefix/share/doc/libspancast-dev/examples
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

# ---- the Debian packages ----
# CPack first builds the tree's preinstall target where the tree's own
# generator has one (Unix Makefiles), which rebuilds a tree whose sources
# changed since it was built, under the tests running beside this one.
# Named as a generator without that step, it packs the tree as built.
check
if ! cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work/deb" \
    -D CPACK_CMAKE_GENERATOR=Ninja >cpack.txt 2>&1; then
    cat cpack.txt
    fail "cpack -G DEB"
    echo "$checks checks, $fails failures"
    exit 1
fi
libpkg=libspancast$soversion
deb_of() { ls "$work"/deb/"$1"_"$version"_*.deb 2>/dev/null | head -n 1; }
debs=()
for pkg in $libpkg libspancast-dev spancast; do
    check
    deb=$(deb_of $pkg)
    if [ -z "$deb" ]; then
        fail "cpack made no $pkg package: $(ls "$work/deb")"
        continue
    fi
    debs+=("$deb")
    dpkg-deb -f "$deb" Package Version >control.txt
    grep -qx "Version: $version" control.txt || fail "$pkg version: $(cat control.txt)"
done
[ "${#debs[@]}" = 3 ] || { echo "$checks checks, $fails failures"; exit 1; }
[ "$(ls "$work"/deb/*.deb | wc -l)" = 3 ] || fail "cpack made other packages: $(ls "$work/deb")"

# contents PKG: the files (not folders) of the package, one a line, with
# LIBDIR (usr/lib or usr/lib/<multiarch>) written as LIBDIR.
contents() {
    dpkg-deb -c "$(deb_of "$1")" | awk '{ print $6 }' | grep -v '/$' | sed 's|^\./||' |
        sed -E 's#^usr/lib/([a-z0-9_]+-linux-gnu[a-z0-9_]*/)?#LIBDIR/#' | sort
}
# has PKG FILE...: each FILE is in PKG; lacks PKG PATTERN...: no file of
# PKG matches an extended regular expression PATTERN.
has() {
    local pkg=$1 f
    shift
    contents "$pkg" >files.txt
    for f; do
        check
        grep -qx "$f" files.txt || fail "$pkg lacks $f: $(tr '\n' ' ' <files.txt)"
    done
}
lacks() {
    local pkg=$1 p
    shift
    contents "$pkg" >files.txt
    for p; do
        check
        ! grep -Eq "$p" files.txt || fail "$pkg holds $(grep -E "$p" files.txt | tr '\n' ' ')"
    done
}
has $libpkg "LIBDIR/libspancast.so.$soversion" "LIBDIR/libspancast.so.$version" \
    LIBDIR/spancast/spancast-oiio.so LIBDIR/spancast/spancast-tiff.so LIBDIR/spancast/spancast-cgal.so \
    LIBDIR/spancast/spancast-xml.so LIBDIR/spancast/spancast-3mf.so \
    LIBDIR/spancast/spancast-text.so LIBDIR/spancast/spancast-exr.so \
    usr/share/doc/$libpkg/copyright
lacks $libpkg '^usr/include/' '^LIBDIR/libspancast\.so$' '^usr/bin/' '^usr/share/man/' \
    'pkgconfig|cmake'
has libspancast-dev usr/include/spancast/spancast.h usr/include/spancast/version.h \
    LIBDIR/libspancast.so LIBDIR/pkgconfig/spancast.pc LIBDIR/cmake/spancast/spancastConfig.cmake \
    LIBDIR/cmake/spancast/spancastTargets.cmake usr/share/man/man3/libspancast.3 \
    usr/share/doc/libspancast-dev/copyright usr/share/doc/libspancast-dev/examples/spans_ray.c
lacks libspancast-dev '^LIBDIR/libspancast\.so\.' '^usr/bin/' '^usr/share/man/man1/' 'spancast-oiio'
has spancast usr/bin/spancast LIBDIR/spancast/spancast-bench LIBDIR/spancast/spancast-view \
    usr/share/man/man1/spancast.1 usr/share/man/man1/spancast-render.1 \
    usr/share/bash-completion/completions/spancast usr/share/doc/spancast/copyright \
    usr/share/doc/spancast/README.md
lacks spancast '^LIBDIR/libspancast' '^usr/include/' 'spancast-oiio' '^usr/share/man/man3/'
# The copyright file is machine-readable (DEP-5): its first field names
# the format, and every paragraph of files names its licence.
check
dpkg-deb --fsys-tarfile "$(deb_of spancast)" | tar -xO ./usr/share/doc/spancast/copyright >copyright.txt
head -n 1 copyright.txt |
    grep -qx 'Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/' ||
    fail "copyright is not DEP-5: $(head -n 1 copyright.txt)"
check
[ "$(grep -c '^Files:' copyright.txt)" = "$(grep -c '^License:' copyright.txt)" ] &&
    grep -qx 'Files: \*' copyright.txt || fail "copyright: a Files paragraph without its License"

# The dependencies. What is linked: from dpkg-shlibdeps (libc6,
# libpng16-16, the OpenEXR and text libraries, libgomp1: the text and EXR
# plugins are scanned with the library, being part of every install);
# OpenImageIO only recommended, since only the plugin loaded on demand
# links it.
field() { dpkg-deb -f "$(deb_of "$1")" "$2"; }
depends=$(field $libpkg Depends)
for pkg in libc6 libpng16-16 libgomp1 libfreetype6 libharfbuzz0b libfontconfig1 libpolyclipping22 \
    libopenexr-3-1-30; do
    check
    echo "$depends" | grep -Eq "(^|, )$pkg( |,|$)" || fail "$libpkg Depends lacks $pkg: $depends"
done
check
[ "$(field $libpkg Section)" = libs ] || fail "$libpkg Section: $(field $libpkg Section)"
check
echo "$depends" | grep -Eq "openimageio|libtiff|libxml2|libzip|lib3mf" && fail "$libpkg Depends on a plugin's library: $depends"
check
[ "$(field $libpkg Recommends)" = "libopenimageio2.4, libtiff6, libgmp10, libmpfr6, libxml2, libzip4, lib3mf1" ] ||
    fail "$libpkg Recommends: $(field $libpkg Recommends)"
check
[ "$(field libspancast-dev Depends)" = "$libpkg (= $version)" ] ||
    fail "libspancast-dev Depends: $(field libspancast-dev Depends)"
check
[ "$(field libspancast-dev Section)" = libdevel ] || fail "libspancast-dev Section"
tool_depends=$(field spancast Depends)
check
echo "$tool_depends" | grep -Eq "(^|, )$libpkg \(= $version\)(,|$)" ||
    fail "spancast Depends lacks $libpkg (= $version): $tool_depends"
check
echo "$tool_depends" | grep -Eq "openimageio|libsdl2" && fail "spancast Depends: $tool_depends"
recommends=$(field spancast Recommends)
for pkg in openscad libopenimageio2.4 libtiff6 libgmp10 libmpfr6 libxml2 libzip4 lib3mf1 libsdl2-2.0-0 libopenmpi3 ffmpeg; do
    check
    echo "$recommends" | grep -Eq "(^|, )$pkg( |,|$)" || fail "spancast Recommends lacks $pkg: $recommends"
done
# Every Depends is a package installed here (the build linked it) or one
# of the three; every Recommends one that apt knows, where apt has package
# lists at all.
names() { tr ',' '\n' | sed 's/(.*//; s/|.*//' | tr -d ' '; }
for pkg in $( (echo "$depends"; echo "$tool_depends") | names | sort -u); do
    check
    [ "$pkg" = "$libpkg" ] || dpkg-query -W "$pkg" >/dev/null 2>&1 ||
        fail "a package Depends on $pkg, which is not installed"
done
if apt-cache show libc6 >/dev/null 2>&1; then
    read -r -a recommended < <(echo "$recommends" | names | tr '\n' ' ')
    apt-cache show --no-all-versions "${recommended[@]}" 2>/dev/null |
        sed -n 's/^Package: //p' | sort -u >known.txt
    for pkg in "${recommended[@]}"; do
        check
        grep -qx "$pkg" known.txt || fail "spancast Recommends $pkg, which apt does not know"
    done
fi
# The shared library is registered: a shlibs entry for packages that link
# it, and ldconfig after install.
check
dpkg-deb --ctrl-tarfile "$(deb_of $libpkg)" | tar -xO ./shlibs 2>/dev/null |
    grep -q "^libspancast $soversion $libpkg (>= $version)$" || fail "$libpkg: no shlibs entry"
check
dpkg-deb --ctrl-tarfile "$(deb_of $libpkg)" | tar -xO ./postinst 2>/dev/null | grep -q ldconfig ||
    fail "$libpkg: postinst does not run ldconfig"

# Installed with dpkg into a scratch root, as an ordinary user may: the
# package database is a copy of this system's, so the Depends on system
# libraries are met by what is installed here and checked like any
# install; the maintainer scripts run outside a chroot, with an ldconfig
# that only notes that it ran.
root=$work/root
mkdir -p "$root/var/lib/dpkg/updates" "$root/var/lib/dpkg/info" stubs
cp /var/lib/dpkg/status "$root/var/lib/dpkg/status"
touch "$root/var/lib/dpkg/available"
printf '#!/bin/sh\necho "ldconfig $*" >>"%s/ldconfig.log"\n' "$work" >stubs/ldconfig
chmod +x stubs/ldconfig
dpkg_root() {
    PATH=$work/stubs:/usr/sbin:/usr/bin:/sbin:/bin \
        dpkg --force-not-root --force-script-chrootless --root="$root" "$@"
}
# libspancast-dev without the library it depends on is refused.
check
if dpkg_root -i "$(deb_of libspancast-dev)" >dpkg-dev.txt 2>&1; then
    fail "dpkg installed libspancast-dev without $libpkg"
fi
grep -q "dependency problems" dpkg-dev.txt || fail "dpkg -i libspancast-dev alone: $(cat dpkg-dev.txt)"
check
if dpkg_root -i "${debs[@]}" >dpkg.txt 2>&1; then
    for pkg in $libpkg libspancast-dev spancast; do
        check
        dpkg_root -s $pkg 2>/dev/null | grep -qx 'Status: install ok installed' ||
            fail "dpkg: $pkg is not installed: $(cat dpkg.txt)"
    done
    check
    grep -q '^ldconfig' ldconfig.log 2>/dev/null || fail "installing $libpkg did not run ldconfig"
else
    fail "dpkg -i of the three packages: $(cat dpkg.txt)"
fi
check
[ -x "$root/usr/bin/spancast" ] || fail "the packages installed no usr/bin/spancast"
debpc=$(dirname "$(ls "$root"/usr/lib/pkgconfig/spancast.pc "$root"/usr/lib/*/pkgconfig/spancast.pc 2>/dev/null | head -n 1)")
deblib=$(dirname "$debpc")
check
out=$("$root/usr/bin/spancast" --version | head -n 1)
[ "$out" = "spancast $version" ] || fail "unpacked spancast --version: '$out'"
check
if LD_DEBUG=files "$root/usr/bin/spancast" render drilled.csg -o deb.tif --imgsize=64,48 -q \
    2>ld-deb.txt; then
    got=$(loaded ld-deb.txt spancast-oiio.so)
    [ "$got" = "$(realpath "$deblib/spancast/spancast-oiio.so")" ] ||
        fail "the packages' tool loaded '$got', not its own plugin"
else
    fail "spancast render from the packages: $(grep -v '^ *[0-9]*:' ld-deb.txt)"
fi
check
mkdir -p ex-deb
if PKG_CONFIG_PATH=$debpc cc -std=c11 "${san_flags[@]}" "$root/usr/share/doc/libspancast-dev/examples/spans_ray.c" \
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
