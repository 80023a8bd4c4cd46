#!/usr/bin/env bash
# The generated bash completion and man page (tools/cli_docs.cpp) name every
# command and every option that `lutbake COMMAND --help` lists, and the
# completion completes: options after a command, a closed list's values.
# Usage: cli_docs_test.sh LUTBAKE DIR (DIR holds lutbake.bash, lutbake.1).
set -u
lutbake=$1 dir=$2 failed=0
bash_file=$dir/lutbake.bash man_file=$dir/lutbake.1
for f in "$bash_file" "$man_file"; do
  [[ -s $f ]] || { echo "missing or empty: $f"; exit 1; }
done
bash -n "$bash_file" || { echo "lutbake.bash: syntax error"; failed=1; }
commands=$("$lutbake" --help | awk '/^Subcommands:/{s=1; next} s && /^$/{exit} s && /^  [a-z]/{print $1}')
[[ $(echo "$commands" | wc -w) -ge 8 ]] || { echo "commands not found in --help"; exit 1; }
for command in $commands; do
  grep -q "\"lutbake $command\"" "$man_file" || { echo "man: no section for $command"; failed=1; }
  grep -q "^        $command)" "$bash_file" || { echo "bash: no options for $command"; failed=1; }
  for option in $("$lutbake" "$command" --help | grep -o -- '^  \(-[a-z],\)\?--[a-z0-9-]*' | sed 's/.*--/--/'); do
    grep -q -- "$(echo "$option" | sed 's/-/\\\\-/g')" "$man_file" ||
      { echo "man: $command $option missing"; failed=1; }
    grep -q -- "^        $command).* $option " "$bash_file" ||
      grep -q -- "^        $command) words=\"$option " "$bash_file" ||
      { echo "bash: $command $option missing"; failed=1; }
  done
done
# The completion itself: options of bake, values of --ndf, the commands.
complete_line() {
  # shellcheck disable=SC1090
  source "$bash_file"
  COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); _lutbake; echo "${COMPREPLY[*]}"
}
[[ $(complete_line lutbake bake --nd) == "--ndf" ]] || { echo "completion: bake --nd"; failed=1; }
[[ $(complete_line lutbake bake --ndf b) == "beckmann" ]] || { echo "completion: --ndf b"; failed=1; }
[[ $(complete_line lutbake ba) == "bake" ]] || { echo "completion: ba"; failed=1; }
[[ $(complete_line lutbake help ev) == "eval" ]] || { echo "completion: help ev"; failed=1; }
exit $failed
