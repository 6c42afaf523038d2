# -h / --help for the bench shell scripts (sourced): prints the script's leading comment block,
# its description with its usage line, and ends the script with exit status 0.
exit_on_help() {  # SCRIPT ARGS...
  local script="$1" a
  shift
  for a in "$@"; do
    if [ "$a" = -h ] || [ "$a" = --help ]; then
      sed -n '2,/^[^#]/s/^# \{0,1\}//p' "$script"
      exit 0
    fi
  done
}
