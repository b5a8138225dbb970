# Columns of a CSV looked up by their header name, so that a column added or moved breaks no script.
# Put in front of an awk program: awk -F, "$(cat scripts/csv-col.awk)"'PROGRAM' FILE...
# In every file the first line that is not a comment (#) is the header: col[NAME] is its column
# number, and the header line goes no further (the program sees the comments and the rows). In the
# program, get(NAME) is this row's value in column NAME; a name the header lacks is one line on
# stderr, "csv-col: FILE: no column NAME", and exit status 2.
FNR == 1 { split("", col); csvcol_header = 0 }
!csvcol_header && !/^#/ { csvcol_header = 1; for (i = 1; i <= NF; i++) col[$i] = i; next }
function get(name) {
    if (!(name in col)) {
        printf "csv-col: %s: no column %s\n", FILENAME, name > "/dev/stderr"
        csvcol_missing = 1
        exit 2
    }
    return $(col[name])
}
END { if (csvcol_missing) exit 2 }
