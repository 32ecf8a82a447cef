#!/usr/bin/env bash
# Writes the man page lbmshape(1) from the binary's own --help: the
# top-level help by help2man, and a COMMANDS section with each command's
# --help, so the page never disagrees with the program. Run by the build
# (cmake/install.cmake) when help2man is installed.
#   scripts/make-man-page.sh LBMSHAPE_BINARY OUT.1
set -euo pipefail
binary=$1 out=$2
include=$(mktemp)
trap 'rm -f "$include"' EXIT
{
  echo "[COMMANDS]"
  for command in $("$binary" --help | sed -n '/^Subcommands:/,$s/^  \([a-z]\+\) .*/\1/p'); do
    echo ".SS $command"
    echo ".nf"
    # Backslashes and leading dots are roff's: escape them.
    "$binary" "$command" --help | sed -e 's/\\/\\e/g' -e 's/^\./\\\&./'
    echo ".fi"
  done
  echo "[SEE ALSO]"
  echo "The documentation in the source tree's docs/ folder, and docs/library.md for the C++ and Python library."
} > "$include"
help2man --no-info --no-discard-stderr --version-string="$("$binary" --version)" \
  --name "surface denoising and morphing with a lattice Boltzmann scheme on Vulkan" \
  --include "$include" --output "$out.tmp" "$binary"
# help2man files the help's "Environment:" under ENVIRONMENT itself, but
# "Exit status:" as a subsection of OPTIONS: make it the section it is.
sed -i 's/^\.SS "Exit status:"$/.SH "EXIT STATUS"/' "$out.tmp"
grep -q '^\.SH "EXIT STATUS"$' "$out.tmp" || { echo "make-man-page.sh: no 'Exit status:' in --help" >&2; exit 1; }
mv "$out.tmp" "$out"
