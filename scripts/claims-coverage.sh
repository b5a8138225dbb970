#!/usr/bin/env bash
# How far the ledger answers the sources: for each source of the catalogue (results/claims-catalogue.csv),
# its claims, those with a ledger row under exactly their ID (a row that tests the source's sentence),
# the verdicts of those rows, the claims met only by the harness's own readings (rows `harness:ID`),
# those the harness cannot test (the catalogue's `needs`: not reproduced) and the testable claims no row
# answers yet, by ID. Rows are read from the claims.csv files given (columns by name).
# usage: claims-coverage.sh [--html] [--require-all] CATALOGUE.csv CLAIMS.csv...
#   --html         a table for the report page instead of Markdown
#   --require-all  exit status 1 when a testable claim has no row under its own ID
# An ID in a claims.csv that the catalogue lacks is one line on stderr and exit status 2.
set -euo pipefail
html= require=
while [ $# -gt 0 ]; do
  case "$1" in
    --html) html=1; shift ;;
    --require-all) require=1; shift ;;
    *) break ;;
  esac
done
[ $# -ge 1 ] || { echo "usage: claims-coverage.sh [--html] [--require-all] CATALOGUE.csv CLAIMS.csv..." >&2; exit 2; }
catalogue=$1
shift
[ -f "$catalogue" ] || { echo "claims-coverage: $catalogue not found" >&2; exit 2; }
csvcol=$(cat "$(dirname "$0")/csv-col.awk")
awk -F, -v html="$html" -v require="$require" -v catalogue="$catalogue" "$csvcol"'
  FILENAME == catalogue && !/^#/ {
    id = get("id"); src[id] = get("source"); needs[id] = get("needs"); ids[++n] = id
    if (!(get("source") in seen)) { seen[get("source")] = 1; sources[++ns] = get("source") }
    next
  }
  FILENAME != catalogue && !/^#/ {
    id = get("id"); base = id; sub(/^harness:/, "", base)
    if (id == "harness") next
    if (!(base in src)) { printf "claims-coverage: %s: ID %s is not in %s\n", FILENAME, id, catalogue > "/dev/stderr"; bad = 1; exit 2 }
    if (id == base) { rows[base]++; verdict[src[base] "," get("verdict")]++ } else reading[base]++
  }
  END {
    if (bad) exit 2
    if (html) print "<table><tr><th>source</th><th>claims</th><th>with a row</th><th>holds</th><th>contradicted</th><th>undecided</th><th>only the harness reading</th><th>not reproduced</th><th>no row yet</th></tr>"
    else { print "| source | claims | with a row | holds | contradicted | undecided | only the harness reading | not reproduced | no row yet |"; print "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- |" }
    missing_all = 0
    for (s = 1; s <= ns; s++) {
      S = sources[s]; total = covered = only = notrep = 0; miss = ""
      for (i = 1; i <= n; i++) {
        id = ids[i]; if (src[id] != S) continue
        total++
        if (rows[id]) covered++
        else if (needs[id] != "") notrep++
        else { if (reading[id]) only++; miss = miss (miss == "" ? "" : " ") id; missing_all++ }
      }
      h = verdict[S ",holds"] + 0; c = verdict[S ",contradicted"] + 0; u = verdict[S ",undecided"] + 0
      if (html) printf "<tr><td>%s</td><td>%d</td><td>%d</td><td class=\"v-holds\">%d rows</td><td class=\"v-contradicted\">%d rows</td><td class=\"v-undecided\">%d rows</td><td>%d</td><td>%d</td><td>%s</td></tr>\n", S, total, covered, h, c, u, only, notrep, miss
      else printf "| %s | %d | %d | %d rows | %d rows | %d rows | %d | %d | %s |\n", S, total, covered, h, c, u, only, notrep, miss
    }
    if (html) print "</table>"
    if (require && missing_all) exit 1
  }' "$catalogue" "$@"
