#!/bin/sh
# commands.sh -- print a help2man include section [COMMANDS] made from each
# subcommand's --help, so the man page always matches the code.
# Usage: man/commands.sh RADIOSITY > commands.x
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.
rad=$1
echo "[COMMANDS]"
for c in solve render formfactor analytic sweep progress animate compare view; do
  echo ".SS \"radiosity $c\""
  echo ".nf"
  # the help is 80 columns wide: it starts at the margin to fit the page
  echo ".in 1n"
  "$rad" $c --help | sed -e 's/\\/\\e/g' -e "s/^\\([.']\\)/\\\\\\&\\1/"
  echo ".fi"
  echo ".in"
done
