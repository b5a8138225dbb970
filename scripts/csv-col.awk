# Columns by name for the awk programs of scripts/*.sh that read the tools' CSV files. Put it before
# the program: awk -F, "$(cat scripts/csv-col.awk)"'PROGRAM' FILE... (mawk has no -e; the text is
# concatenated). In each file the first line that is not a "# key value" metadata line is the
# header; it is consumed here (the program never sees it), and v("NAME") is the current row's cell
# of column NAME: a missing column is the error line "FILE: no column 'NAME'" and exit status 2, so
# a column added, moved or renamed never silently shifts what a script reads.
FNR == 1 { split("", csvcol); csvhead = 1 }
csvhead && !/^#/ { csvhead = 0; for (i = 1; i <= NF; i++) csvcol[$i] = i; next }
function v(name) {
  if (!(name in csvcol)) { printf "%s: no column '%s'\n", FILENAME, name > "/dev/stderr"; exit 2 }
  return $(csvcol[name])
}
