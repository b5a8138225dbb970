# Thesis Figure 4.2: PSSMLT on a square wall at 1024, 512, 256 pixels and with resolution-scaled
# steps (--rap-resolution) at 256. Left: the error's correlation length in pixels per resolution;
# middle: relMSE at equal mutations per pixel; right: small-step acceptance on the glossy-to-glossy
# scene (scenes/wall-glossy) without and with --rap-resolution. Error bars: standard errors over seeds.
# usage: gnuplot -e "csv='results/fig4.2/fig4.2.csv'; out='results/fig4.2/fig4.2'" scripts/fig4.2.gp
set datafile separator ","
set errorbars small
set grid
set logscale x 2
set xrange [180:1450]
set xtics ("256" 256, "512" 512, "1024" 1024)
set xlabel "resolution (pixels, square)"
set key top left box opaque
# rows of one quantity of the plain PSSMLT configurations, and of the resolution-scaled one
pss(q) = sprintf("< grep '^pssmlt-[0-9]*,[0-9]*,%s,' '%s'", q, csv)
rap(q) = sprintf("< grep '^rap-resolution-256,[0-9]*,%s,' '%s'", q, csv)
glossy(c) = sprintf("< grep '^glossy-%s-[0-9]*,[0-9]*,small_accept,' '%s'", c, csv)
do for [fmt in "png pdf"] {
    if (fmt eq "png") { set terminal pngcairo size 1450,420 font ",11" } else { set terminal pdfcairo size 10in,3in font ",9" }
    set output out.".".fmt
    set multiplot layout 1,3 title "PSSMLT on a diffuse wall at three resolutions (thesis Fig. 4.2); right: a glossy-to-glossy scene"
    set ylabel "error correlation length (pixels)"
    set yrange [0:*]
    plot pss("l_x") using 2:5:6 with yerrorlines lw 2 pt 7 lc rgb "#c0392b" title "PSSMLT, horizontal", \
         pss("l_y") using 2:5:6 with yerrorlines lw 2 pt 5 dt 2 lc rgb "#c0392b" title "PSSMLT, vertical", \
         rap("l") using ($2*1.04):5:6 with yerrorbars pt 9 ps 1.5 lc rgb "#2471a3" title "--rap-resolution (mean of x, y)"
    set ylabel "relMSE at equal mutations per pixel"
    set key bottom left
    plot pss("relmse") using 2:5:6 with yerrorlines lw 2 pt 7 lc rgb "#c0392b" title "PSSMLT", \
         rap("relmse") using ($2*1.04):5:6 with yerrorbars pt 9 ps 1.5 lc rgb "#2471a3" title "--rap-resolution"
    set ylabel "small-step acceptance, glossy-to-glossy scene"
    set yrange [*:*]
    set key bottom right
    plot glossy("pssmlt") using 2:5:6 with yerrorlines lw 2 pt 7 lc rgb "#c0392b" title "PSSMLT", \
         glossy("rap-resolution") using 2:5:6 with yerrorlines lw 2 pt 9 lc rgb "#2471a3" title "--rap-resolution"
    unset multiplot
}
