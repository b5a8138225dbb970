# Error vs time of bin/ch6_equal's summary.csv: relMSE (mean +- standard error over seeds) against the
# budget, log-log, one line per method. Called with csv, out (prefix) and name.
set datafile separator ','
set terminal pngcairo size 640,420 font ',10'
set output out.'.png'
set logscale xy
set xlabel 'time budget per run (CPU s per thread)'
set ylabel 'relMSE'
set title 'error vs time: '.name
set key top right
set grid
methods = system("awk -F, '!/^#/ && $1 != \"scene\" && !s[$2]++ {printf \"%s \", $2}' ".csv)
plot for [m in methods] csv using ($3):(strcol(2) eq m ? $5 : 1/0):6 with yerrorlines title m
