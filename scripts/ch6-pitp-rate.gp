# make pitp-rate's plot of one scene: PITP's error against its technique-perturbation rate P, read
# from bin/ch6_equal's summary.csv (methods named pP): relMSE, relMSE without the normalisation's
# part and median block relMSE (left), and
# the splotch statistics, error share surviving an 8x8 blur and block-relMSE spread (right), each
# mean +- standard error over seeds. Called with csv, out (prefix) and name.
set datafile separator ','
set terminal pngcairo size 960,400 font ',10'
set output out.'.png'
col(name) = int(system(sprintf("awk -F, '!/^#/ { for (i = 1; i <= NF; i++) if ($i == \"%s\") print i; exit }' %s", name, csv)))
cm = col('method'); cr = col('relmse'); crs = col('relmse_se'); cb = col('block_median_relmse')
cbs = col('block_median_relmse_se'); cl = col('blur8_share'); cls = col('blur8_share_se')
cp = col('block_spread'); cps = col('block_spread_se'); cn = col('relmse_scaled'); cns = col('relmse_scaled_se')
if (cm * cr * crs * cb * cbs * cl * cls * cp * cps * cn * cns == 0) { print csv.": a column is missing"; exit status 2 }
# P from the method's name pP; other methods are left out
P(s) = (s[1:1] eq 'p' && strlen(s) > 1) ? real(s[2:]) : 1/0
set multiplot layout 1,2 title 'PITP technique-perturbation rate: '.name
set xlabel 'P (probability of a technique perturbation before a small step)'
set xrange [-0.05:1.05]
set grid
set key top right
set ylabel 'relative MSE'
plot csv using (P(strcol(cm))):(column(cr)):(column(crs)) with yerrorlines title 'relMSE', \
     csv using (P(strcol(cm))):(column(cn)):(column(cns)) with yerrorlines title 'relMSE without the normalisation', \
     csv using (P(strcol(cm))):(column(cb)):(column(cbs)) with yerrorlines title 'median block relMSE'
set ylabel 'splotch statistic (log scale: the two differ in size)'
set logscale y
plot csv using (P(strcol(cm))):(column(cl)):(column(cls)) with yerrorlines title 'error share after 8x8 blur', \
     csv using (P(strcol(cm))):(column(cp)):(column(cps)) with yerrorlines title 'block-relMSE spread (CV)'
unset multiplot
