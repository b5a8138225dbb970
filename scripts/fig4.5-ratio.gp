# Thesis Figure 4.5's ratio: acceptance of each run over MMLT large steps' per path length, and
# MCTLS's over the thesis-count MMLT large steps' (k + 2 techniques, t = 0 a failed try), and the
# ratio's first factor: MCTLS's share of proposals that carry light over MMLT's.
# usage: gnuplot -e "csv='results/fig4.5/fig4.5-ratios.csv'; out='results/fig4.5/fig4.5-ratio'" scripts/fig4.5-ratio.gp
set datafile separator ","
set key at screen 0.5, screen 0.02 center bottom box
set bmargin 11
set title "Acceptance ratios per path length (scenes/ajar)"
set xlabel "path length (segments)"
set ylabel "acceptance ratio"
set grid ytics
set xtics 1
set offsets 0.5, 0.5, 0, 0
set yrange [0:*]
set errorbars small
sel(m, col) = (strcol(1) eq m) ? column(col) : NaN
do for [fmt in "png pdf"] {
    if (fmt eq "png") { set terminal pngcairo size 800,660 font ",11" } else { set terminal pdfcairo size 5in,4in font ",9" }
    set output out.".".fmt
    plot csv skip 0 using 2:(sel("mctls/mmlt-large", 3)):(sel("mctls/mmlt-large", 4)) with yerrorlines lw 2 pt 5 title "MCTLS / MMLT large steps (k + 1 techniques)", \
         csv skip 0 using 2:(sel("light:mctls/mmlt-large", 3)):(sel("light:mctls/mmlt-large", 4)) with yerrorlines lw 2 dt 3 pt 3 lc rgb "#444444" title "proposals with light, MCTLS / MMLT", \
         csv skip 0 using 2:(sel("mctls/mctls-tries1-t0", 3)):(sel("mctls/mctls-tries1-t0", 4)) with yerrorlines lw 2 dt 2 pt 6 title "MCTLS / MMLT large steps among k + 2 (thesis count)", \
         csv skip 0 using 2:(sel("mctls-tries4/mmlt-large", 3)):(sel("mctls-tries4/mmlt-large", 4)) with yerrorlines lw 1 pt 8 title "4 drawn trials / MMLT", \
         csv skip 0 using 2:(sel("mctls-tries2/mmlt-large", 3)):(sel("mctls-tries2/mmlt-large", 4)) with yerrorlines lw 1 pt 4 title "2 drawn trials / MMLT", \
         csv skip 0 using 2:(sel("mctls-tries1/mmlt-large", 3)):(sel("mctls-tries1/mmlt-large", 4)) with yerrorlines lw 1 pt 1 title "1 drawn trial / MMLT (check: 1)"
}
