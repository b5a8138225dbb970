# Thesis Figure 6.1: average acceptance of small steps per path length, MMLT (left) vs PITP (right),
# split into steps that change the technique and steps that do not.
# usage: gnuplot -e "csv='results/fig6.1/fig6.1.csv'; out='results/fig6.1/fig6.1'" scripts/fig6.1.gp
set datafile separator ","
set key top right box opaque
set xlabel "path length (segments)"
set grid ytics
set xtics 1
set xrange [1.5:12.5]
set yrange [0:1]
set errorbars small
# one series per (method, technique changed), filtered so that lines join its points only
rows(m, c) = sprintf("< grep '^%s,[0-9]*,%s,' %s", m, c, csv)
do for [fmt in "png pdf"] {
    if (fmt eq "png") { set terminal pngcairo size 1100,450 font ",11" } else { set terminal pdfcairo size 7in,2.9in font ",9" }
    set output out.".".fmt
    set multiplot layout 1,2 title "Average acceptance of small steps per path length (scenes/ajar; thesis Fig. 6.1)"
    do for [m in "mmlt pitp"] {
        set title (m eq "mmlt" ? "MMLT" : "PITP")
        set ylabel (m eq "mmlt" ? "average acceptance probability E[min(1, a)]" : "")
        plot rows(m, "no") using ($2-0.06):5:6 with yerrorlines lw 2 pt 7 title "does not change the technique", \
             rows(m, "yes") using ($2+0.06):5:6 with yerrorlines lw 2 pt 5 title "changes the technique"
    }
    unset multiplot
}
