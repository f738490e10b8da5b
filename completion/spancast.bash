# bash completion for spancast(1): commands, each command's options and
# model files (.csg, .scad, .stl, .off). The commands and options are read
# from `spancast --help` and `spancast COMMAND --help`, so they follow the
# installed tool. Installed as share/bash-completion/completions/spancast;
# plain bash, no helpers from the bash-completion package needed.

# _spancast_commands SPANCAST: the commands of the usage lines
# ("usage: spancast render MODEL ..." / "       spancast info MODEL").
_spancast_commands()
{
    "$1" --help 2>/dev/null |
        awk '/^(usage:)? *spancast [a-z]/ { sub(/^(usage:)? *spancast /, ""); split($0, w, " "); if (!seen[w[1]]++) print w[1] }'
}

# _spancast_command_options SPANCAST COMMAND: the options `SPANCAST COMMAND
# --help` lists for COMMAND, one a line. When that text describes several
# commands, an option belongs to COMMAND when it is on one of COMMAND's
# usage lines (and their continuation lines), in a "COMMAND options:" or
# "A, B and COMMAND options:" (or "... limits:") block (up to the next
# blank line), or in a block under another heading ("preview options
# ...:", "report options:") that follows COMMAND's.
_spancast_command_options()
{
    "$1" "$2" --help 2>/dev/null | awk -v cmd="$2" '
        function options(line,    rest, m) {
            rest = " " line " "
            while (match(rest, /[^A-Za-z0-9_-](--[a-z][a-z0-9-]*|-[a-zA-Z])[^A-Za-z0-9_-]/)) {
                m = substr(rest, RSTART + 1, RLENGTH - 2)
                if (!seen[m]++) found[++n] = m
                rest = substr(rest, RSTART + RLENGTH - 1)
            }
        }
        /^(usage:)? *spancast -/ { mine = 0; block = 0; all = all "\n" $0; next }
        /^(usage:)? *spancast [a-z]/ {
            line = $0
            sub(/^(usage:)? *spancast /, "", line)
            split(line, w, " ")
            if (!(w[1] in commands)) { commands[w[1]] = 1; ncommands++ }
            mine = (w[1] == cmd); block = 0
            if (mine) { usage = usage "\n" $0 } else { all = all "\n" $0 }
            next
        }
        # "CMD options:" opens a block of CMD; a block of another heading
        # ("preview options (CAD-style renders):", "report options:")
        # belongs to the command whose block came before it.
        # "A, B and C options:" (or "... limits:") is a block of each
        # command it names.
        /^[a-z][a-z, -]* (options|limits)( \([^)]*\))?:$/ {
            named = 0; ours = 0
            for (i = 1; i <= NF && $i !~ /^(options|limits)/; i++) {
                word = $i; sub(/,$/, "", word)
                if (word in commands) { named++; if (word == cmd) ours = 1 }
            }
            if (named == 1) owner = $1
            block = named > 1 ? ours : (owner == cmd); mine = 0; next
        }
        /^[ \t]*$/ { block = 0; mine = 0; all = all "\n"; next }
        mine || block { usage = usage "\n" $0; next }
        { all = all "\n" $0 }
        END {
            # Help of this command alone: every option in it is its own.
            if (ncommands <= 1) usage = usage "\n" all
            k = split(usage, lines, "\n")
            for (i = 1; i <= k; i++) options(lines[i])
            for (i = 1; i <= n; i++) print found[i]
        }'
}

_spancast()
{
    local spancast=$1 cur=${COMP_WORDS[COMP_CWORD]} prev=
    ((COMP_CWORD > 0)) && prev=${COMP_WORDS[COMP_CWORD - 1]}
    local IFS=$'\n'
    COMPREPLY=()
    if ((COMP_CWORD == 1)); then
        mapfile -t COMPREPLY < <(compgen -W "$(_spancast_commands "$spancast")
--help
--version" -- "$cur")
        return
    fi
    local command=${COMP_WORDS[1]} word k
    # A value: "--opt=VALUE" in one word (bash splits at '=' when '=' is in
    # COMP_WORDBREAKS), or the word after an option that takes one.
    if [[ $cur == --*=* ]]; then
        cur=${cur#*=}
        prev="="
    elif [[ $cur == "=" ]]; then
        cur=
        prev="="
    fi
    if [[ $prev == "=" || $prev == -o ]] ||
        { [[ $prev == --* ]] && "$spancast" "$command" --help 2>/dev/null | grep -q -- "$prev="; }; then
        compopt -o filenames 2>/dev/null
        mapfile -t COMPREPLY < <(compgen -f -- "$cur")
        return
    fi
    if [[ $cur == -* ]]; then
        local options
        options=$(_spancast_command_options "$spancast" "$command")
        # "[camera options]" on a usage line: render's camera options.
        if "$spancast" "$command" --help 2>/dev/null | grep -q "spancast $command .*camera options\|^ .*\[camera options\]"; then
            options+=$'\n'"--camera"$'\n'"--imgsize"$'\n'"--fov"$'\n'"--projection"$'\n'"--viewall"$'\n'"--autocenter"
        fi
        mapfile -t COMPREPLY < <(compgen -W "$options" -- "$cur")
        return
    fi
    # The model: the first word after the command that is not an option.
    for ((k = 2; k < COMP_CWORD; k++)); do
        word=${COMP_WORDS[k]}
        [[ $word == -* || ${COMP_WORDS[k - 1]} == -o ]] || return 0
    done
    compopt -o filenames 2>/dev/null
    for word in $(compgen -f -- "$cur"); do
        if [[ -d $word ]]; then
            COMPREPLY+=("$word")
        else
            case $word in
            *.csg | *.scad | *.stl | *.off) COMPREPLY+=("$word") ;;
            esac
        fi
    done
}
complete -F _spancast spancast
