# Draws docs/finish_line.png from a scripts/describe_finishes.py --out CSV: for every goal episode,
# how far beside the path it ended (x) and how many metres of path were left (y), with the 5 m
# goal circle's prediction sqrt(25 - d^2) and the 99 % line of the shortest and longest test
# paths (300 and 586 m: 3.0 and 5.9 m left). The farther beside the path a vessel enters the
# circle, the less path it leaves, so the more progress it is given. Run from the repository's
# root: gnuplot -e "csv='runs/finish/finishes.csv'" scripts/finish_line.gp
if (!exists("csv")) csv = 'runs/finish/finishes.csv'
set terminal pngcairo size 900,600 enhanced font 'DejaVu Sans,11'
set output 'docs/finish_line.png'
set datafile separator ','
set key top right box opaque
set grid
set title "Where goal episodes end: 1,000 test scenarios, every agent replayed"
set xlabel 'beside the path at the last step, m (|cross-track error|)'
set ylabel 'path left before its end, m'
set xrange [0:8]
set yrange [0:6.5]
circle(d) = d < 5 ? sqrt(25 - d * d) : NaN
plot csv skip 1 using 6:($3 == 1 ? $7 : NaN) with points pt 7 ps 0.3 lc rgb '#802060a0' \
       title 'goal episodes', \
     circle(x) with lines lw 3 lc rgb '#d04020' title 'entering the 5 m circle: sqrt(25 - d^2)', \
     3.0 with lines dt 2 lw 2 lc rgb '#404040' title '99 % line, 300 m path', \
     5.86 with lines dt 3 lw 2 lc rgb '#404040' title '99 % line, 586 m path'
