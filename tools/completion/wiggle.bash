# Bash completion for wiggle (installed as share/bash-completion/completions/wiggle):
# subcommands, their options, config keys after --set, files and directories elsewhere.
_wiggle() {
  local cur prev words cword
  _init_completion || return
  local commands="run sweep boundary model plot export-lammps status report rate"
  if [[ $cword -eq 1 ]]; then
    COMPREPLY=($(compgen -W "$commands --help --version" -- "$cur"))
    return
  fi
  case "$prev" in
    --set)
      # section.key= for every key that `wiggle run --help` lists under its [section]
      local keys
      keys=$(wiggle run --help 2>/dev/null |
             awk '/^\[[a-z]+\]/ {s = substr($1, 2, length($1) - 2)} /^  [a-z_]+ = / {print s "." $1 "="}')
      COMPREPLY=($(compgen -W "$keys" -- "$cur"))
      compopt -o nospace
      return ;;
    --out)  # a directory, except report's HTML file
      if [[ "${words[1]}" == report ]]; then _filedir html; else _filedir -d; fi
      return ;;
    --threads|--jobs|--case) return ;;
  esac
  local options
  case "${words[1]}" in
    run) options="--set --out --threads --fixed-threads --resume --no-plot --check --help" ;;
    sweep) options="--out --jobs --threads --dry-run --local --case --help" ;;
    model) options="--shape --vertices --angle --format --periods --amplitude --geometry --clump --surface --help" ;;
    plot) options="--format --movie --times --out --geometry --help" ;;
    export-lammps) options="--set --out --threads --help" ;;
    boundary) options="--set --vary --range --points --resolution --beds --scatter --over --rate --out --jobs --threads --dry-run --help" ;;
    rate) options="--from --to --band --write --help" ;;
    status) options="--help" ;;
    report) options="--out --help" ;;
  esac
  if [[ "$cur" == -* ]]; then
    COMPREPLY=($(compgen -W "$options" -- "$cur"))
  else
    _filedir
  fi
}
complete -F _wiggle wiggle
