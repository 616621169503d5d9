# The scripts' one way to read their command line (sourced by scripts/*.sh; bash).
#
#   script_options NAME SPEC... -- "$@"
#
# Each SPEC declares one option:
#   --option=variable          the option takes a value: `--option VALUE` and `--option=VALUE` set $variable
#   --option=variable=VALUE    a switch: `--option` sets $variable to VALUE (`--no-real=real=` empties $real)
#   '*'                        arguments that are not options of the script are kept, in order, in the array
#                              script_rest (options for the program the script runs) instead of refused
# The script's defaults are the variables' values before the call. -h and --help print the script's usage()
# on stdout and exit 0. A lone -- ends the script's options: what follows is appended to script_rest.
# A usage error exits 2 with one line on stderr, `NAME: unknown argument 'X'`, `NAME: --option needs a
# value` or `NAME: --option takes no value`, followed by usage(). The last of repeated options wins.
# usage() is the script's leading comment block (script_header) unless the script defines its own after
# sourcing this file.

script_header() { sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$0"; }
usage() { script_header; }

script_options() {
  local _so_name=$1 _so_pass=0 _so_arg _so_opt _so_value _so_inline _so_spec _so_target _so_found
  local -a _so_specs=()
  shift
  while (($#)) && [ "$1" != -- ]; do
    if [ "$1" = '*' ]; then _so_pass=1; else _so_specs+=("$1"); fi
    shift
  done
  (($#)) && shift  # the -- between the specs and the arguments
  script_rest=()
  while (($#)); do
    _so_arg=$1
    shift
    case "$_so_arg" in
      -h|--help) usage; exit 0 ;;
      --) script_rest+=("$@"); return 0 ;;
    esac
    _so_opt=${_so_arg%%=*} _so_inline=0 _so_value=""
    if [[ "$_so_arg" == --*=* ]]; then _so_inline=1 _so_value=${_so_arg#*=}; fi
    _so_found=0
    for _so_spec in "${_so_specs[@]}"; do
      [ "${_so_spec%%=*}" = "$_so_opt" ] || continue
      _so_found=1 _so_target=${_so_spec#*=}
      if [[ "$_so_target" == *=* ]]; then  # a switch
        ((!_so_inline)) || _script_usage_error "$_so_name" "$_so_opt takes no value"
        printf -v "${_so_target%%=*}" '%s' "${_so_target#*=}"
      else
        if ((!_so_inline)); then
          (($#)) || _script_usage_error "$_so_name" "$_so_opt needs a value"
          _so_value=$1
          shift
        fi
        printf -v "$_so_target" '%s' "$_so_value"
      fi
      break
    done
    if ((!_so_found)); then
      ((_so_pass)) || _script_usage_error "$_so_name" "unknown argument '$_so_arg'"
      script_rest+=("$_so_arg")
    fi
  done
}

_script_usage_error() {
  echo "$1: $2" >&2
  usage >&2
  exit 2
}
