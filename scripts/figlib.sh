# figlib.sh -- what the figure scripts share; sourced by scripts/figures.sh,
# figures-hemicube.sh and figures-adaptive.sh (not run on its own).
# Copyright (C) 2026 The radiosity authors.  GPLv3+, see COPYING.

# fig_args "$@": the three arguments RADIOSITY DATADIR OUTDIR, checked.
fig_args() {
  if [ $# -ne 3 ]; then
    echo "Usage: $0 RADIOSITY DATADIR OUTDIR" >&2
    exit 2
  fi
  [ -x "$1" ] || { echo "$0: $1 is not an executable" >&2; exit 1; }
}

# html_escape TEXT: TEXT for HTML text and attribute values.
html_escape() { printf '%s' "$1" | sed 's/&/\&amp;/g; s/</\&lt;/g; s/>/\&gt;/g; s/"/\&quot;/g'; }
