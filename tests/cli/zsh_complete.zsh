# Completion in an interactive zsh (tests/cli/test_install.sh): zsh -f zsh_complete.zsh FPATH_DIR
# PATH_DIR FOLDER WORDS prints what the line WORDS<Tab> shows in a fresh zsh with compinit, the
# pointcalc definition found on FPATH_DIR and the program on PATH_DIR, run in FOLDER; the
# terminal's escape sequences are left for the caller to strip.
zmodload zsh/zpty
zpty -b z zsh -f -i
zpty -w z "PS1='%% '; fpath=($1 \$fpath); autoload -U compinit; compinit -u -D; PATH=$2:\$PATH; cd $3"
sleep 1
zpty -w -n z "$4"$'\t'
sleep 1.5
local out= chunk
while zpty -r -t z chunk; do out+=$chunk; done
print -r -- "$out"
zpty -d z
