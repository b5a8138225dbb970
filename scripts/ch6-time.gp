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
# the columns by name: the header is the first line that is not a "# key value" line
col(name) = int(system(sprintf("awk -F, '!/^#/ { for (i = 1; i <= NF; i++) if ($i == \"%s\") print i; exit }' %s", name, csv)))
cb = col('budget'); cm = col('method'); cr = col('relmse'); cs = col('relmse_se')
if (cb * cm * cr * cs == 0) { print csv.": no column budget, method, relmse or relmse_se"; exit status 2 }
methods = system(sprintf("awk -F, '!/^#/ && n++ && !s[$%d]++ {printf \"%%s \", $%d}' %s", cm, cm, csv))
plot for [m in methods] csv using (column(cb)):(strcol(cm) eq m ? column(cr) : 1/0):(column(cs)) with yerrorlines title m
