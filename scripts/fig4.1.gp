# Thesis Figure 4.1: the shape of PSSMLT's noise on a 16:9 wall. Autocorrelation profiles of the
# error image along x and y (mean over seeds, error bars = standard errors), normalised at lag 1
# (the lag-0 value also holds each splat's own white noise), for isotropic and resolution-aware
# small steps; the correlation length is where a profile crosses 1/e.
# usage: gnuplot -e "csv='results/fig4.1/fig4.1-profiles.csv'; out='results/fig4.1/fig4.1-profiles'; maxlag=20" scripts/fig4.1.gp
set datafile separator ","
if (!exists("maxlag")) maxlag = 20
set key top right box opaque
set title "Error autocorrelation of PSSMLT on a 16:9 wall (thesis Fig. 4.1)"
set xlabel "lag (pixels)"
set ylabel "rho(lag) / rho(1)"
set grid
set xrange [1:maxlag]
set yrange [-0.1:1.05]
set errorbars small
# the lag-1 values, read first
stats csv using ((strcol(1) eq "iso" && $2 == 1) ? $3 : NaN) nooutput
ix = STATS_max
stats csv using ((strcol(1) eq "iso" && $2 == 1) ? $5 : NaN) nooutput
iy = STATS_max
stats csv using ((strcol(1) eq "rap" && $2 == 1) ? $3 : NaN) nooutput
rx = STATS_max
stats csv using ((strcol(1) eq "rap" && $2 == 1) ? $5 : NaN) nooutput
ry = STATS_max
sel(v, col, n) = (strcol(1) eq v && $2 >= 1) ? column(col) / n : NaN
do for [fmt in "png pdf"] {
    if (fmt eq "png") { set terminal pngcairo size 800,500 font ",11" } else { set terminal pdfcairo size 5in,3.2in font ",9" }
    set output out.".".fmt
    plot csv skip 0 using 2:(sel("iso", 3, ix)):(sel("iso", 4, ix)) with yerrorlines lw 2 pt 7 lc rgb "#c0392b" title "isotropic, horizontal", \
         csv skip 0 using 2:(sel("iso", 5, iy)):(sel("iso", 6, iy)) with yerrorlines lw 2 pt 5 dt 2 lc rgb "#c0392b" title "isotropic, vertical", \
         csv skip 0 using 2:(sel("rap", 3, rx)):(sel("rap", 4, rx)) with yerrorlines lw 2 pt 7 lc rgb "#2471a3" title "resolution-aware, horizontal", \
         csv skip 0 using 2:(sel("rap", 5, ry)):(sel("rap", 6, ry)) with yerrorlines lw 2 pt 5 dt 2 lc rgb "#2471a3" title "resolution-aware, vertical", \
         exp(-1) with lines lc rgb "gray40" dt 3 title "1/e"
}
