# Thesis Figure 4.5: average acceptance probability per path length, MMLT large steps vs MCTLS, and
# (thin) MCTLS with a fixed number of drawn trials (mctls-triesN; -t0: among k + 2 techniques).
# usage: gnuplot -e "csv='results/fig4.5/fig4.5.csv'; out='results/fig4.5/fig4.5'" scripts/fig4.5.gp
set datafile separator ","
set key top left box opaque
set title "Average acceptance of large steps per path length (scenes/ajar; thesis Fig. 4.5)"
set xlabel "path length (segments)"
set ylabel "average acceptance probability E[min(1, a)]"
set grid ytics
set xtics 1
set offsets 0.5, 0.5, 0, 0
set yrange [0:*]
set errorbars small
sel(m, col) = (strcol(1) eq m) ? column(col) : NaN
do for [fmt in "png pdf"] {
    if (fmt eq "png") { set terminal pngcairo size 800,500 font ",11" } else { set terminal pdfcairo size 5in,3.2in font ",9" }
    set output out.".".fmt
    plot csv skip 0 using ($2-0.08):(sel("mmlt-large", 4)):(sel("mmlt-large", 5)) with yerrorlines lw 2 pt 7 title "MMLT large steps", \
         csv skip 0 using ($2+0.08):(sel("mctls", 4)):(sel("mctls", 5)) with yerrorlines lw 2 pt 5 title "MCTLS", \
         csv skip 0 using 2:(sel("mctls-tries1-t0", 4)):(sel("mctls-tries1-t0", 5)) with yerrorlines lw 1 dt 2 pt 6 title "MMLT large steps among k + 2 (thesis count)", \
         csv skip 0 using 2:(sel("mctls-tries2", 4)):(sel("mctls-tries2", 5)) with yerrorlines lw 1 pt 4 title "2 drawn trials", \
         csv skip 0 using 2:(sel("mctls-tries4", 4)):(sel("mctls-tries4", 5)) with yerrorlines lw 1 pt 8 title "4 drawn trials"
}
