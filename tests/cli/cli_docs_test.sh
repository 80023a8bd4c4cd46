#!/usr/bin/env bash
# The generated bash, zsh and fish completions and man page
# (tools/cli_docs.cpp) name every command and every option that
# `lutbake COMMAND --help` lists, and the completions complete: options after
# a command, a closed list's values. zsh and fish (scripts/test.sh installs
# them) are run where present; without them their parts say so and skip.
# Usage: cli_docs_test.sh LUTBAKE DIR (DIR holds lutbake.bash, _lutbake,
# lutbake.fish, lutbake.1).
set -u
lutbake=$1 dir=$2 failed=0
bash_file=$dir/lutbake.bash man_file=$dir/lutbake.1 zsh_file=$dir/_lutbake fish_file=$dir/lutbake.fish
for f in "$bash_file" "$man_file" "$zsh_file" "$fish_file"; do
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
    grep -q -- "'$option\[\|,$option}\|{$option," "$zsh_file" || { echo "zsh: $command $option missing"; failed=1; }
    grep -q -- "from $command' .*-l ${option#--} " "$fish_file" ||
      { echo "fish: $command $option missing"; failed=1; }
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
# zsh: the function run with _arguments and _describe replaced by printers of
# what they were given (a real completion needs a terminal).
if command -v zsh >/dev/null; then
  zsh -n "$zsh_file" || { echo "_lutbake: syntax error"; failed=1; }
  zsh_complete() {
    zsh -f -c '_describe() { print -l -- "${(@P)${@[-1]}}"; }; _arguments() { print -l -- "$@"; }
      source "$1"; words=(${=2}); CURRENT=$3; _lutbake' zsh "$zsh_file" "$1" "$2"
  }
  zsh_complete "lutbake ba" 2 | grep -q "^bake:Bake tables" || { echo "zsh: commands"; failed=1; }
  zsh_complete "lutbake bake --nd" 3 | grep -q "^--ndf\[.*\]:NAME:(ggx *beckmann)$" ||
    { echo "zsh: bake --ndf and its values"; failed=1; }
  zsh_complete "lutbake check" 3 | grep -q "^\*:file:_files$" || { echo "zsh: check DIR"; failed=1; }
else
  echo "zsh not installed: its completion's syntax and behaviour not checked"
fi
# fish: its own completion engine (complete -C) on the generated file.
if command -v fish >/dev/null; then
  fish -n "$fish_file" || { echo "lutbake.fish: syntax error"; failed=1; }
  fish_complete() { fish --no-config -c "source '$fish_file'; complete -C '$1'" | cut -f1 | sort | tr '\n' ' '; }
  [[ $(fish_complete "lutbake bake --nd") == "--ndf " ]] || { echo "fish: bake --nd"; failed=1; }
  [[ $(fish_complete "lutbake bake --ndf ") == "beckmann ggx " ]] || { echo "fish: --ndf values"; failed=1; }
  [[ $(fish_complete "lutbake ba") == "bake " ]] || { echo "fish: ba"; failed=1; }
  [[ $(fish_complete "lutbake check --threads ") == "" ]] || { echo "fish: --threads N completes files"; failed=1; }
else
  echo "fish not installed: its completion's syntax and behaviour not checked"
fi
exit $failed
