#!/usr/bin/env bash
# Markdown table of results/fig4.1/fig4.1.csv: per variant the horizontal and vertical correlation
# lengths of the error, their ratio, the lag-1 autocorrelations, relMSE and small-step acceptance,
# each mean ± standard error over seeds; then the thesis's claim. usage: fig4.1-table.sh CSV > MD
set -euo pipefail
cols=$(cat "$(dirname "$0")/csv-col.awk")
awk -F, "$cols"'
/^# resolution/ { res = $0; sub(/^# resolution /, "", res) }
/^# mutations_per_pixel/ { mpp = $0; sub(/^# mutations_per_pixel /, "", mpp) }
/^# p_large/ { pl = $0; sub(/^# p_large /, "", pl) }
/^#/ { next }
{ v = get("variant"); q = get("quantity"); m[v, q] = get("mean"); s[v, q] = get("se"); n = get("seeds") }
function f(v, q, d) { return sprintf("%." d "f ± %." d "f", m[v, q], s[v, q]) }
END {
    printf "PSSMLT on `scenes/wall` at %s, %s mutations per pixel, p_large = %s, %d seeds (mean ± standard error).\n\n", res, mpp, pl, n
    print "| small steps | l_x (px) | l_y (px) | l_x / l_y | rho_x(1), rho_y(1) | relMSE | small-step acceptance |"
    print "| --- | ---: | ---: | ---: | ---: | ---: | ---: |"
    split("iso rap", V, " "); name["iso"] = "isotropic (PSSMLT)"; name["rap"] = "resolution-aware (`--rap`)"
    for (i = 1; i <= 2; i++) {
        v = V[i]
        printf "| %s | %s | %s | %s | %.3f, %.3f | %s | %.4f |\n", name[v], f(v, "l_x", 2), f(v, "l_y", 2), f(v, "ratio", 3), \
            m[v, "rho1_x"], m[v, "rho1_y"], f(v, "relmse", 4), m[v, "small_accept"]
    }
    split(res, wh, "x")
    printf "\nThesis: isotropic steps stretch the noise horizontally by about the aspect ratio (%.2f); resolution-aware steps make it isotropic (ratio near 1).\n", wh[1] / wh[2]
}' "$1"
