# Draws docs/handover_rules.png from docs/handover_rules.csv: issue 16's hand-over rules for the
# cautious helmsmen on the validation scenarios (means over 5 seed pairs), progress and collisions
# against cross-track error, the ranges' front as a line and the goal (progress >= 97 %,
# collisions <= 3 %, cross-track error <= 17 m) shaded. Run from the repository's root:
# gnuplot scripts/handover_rules.gp
set terminal pngcairo size 1500,650 enhanced font 'DejaVu Sans,11'
set output 'docs/handover_rules.png'
set datafile separator ','
data = 'docs/handover_rules.csv'
family(name) = (strcol(1) eq name) ? 1 : NaN
families = "rule member disagreement"
title_of(i) = i == 1 ? 'other hand-over rules' : i == 2 ? 'other members' : \
              "the members' disagreement (moment or thrust) also hands over"
points = "9 5 7"
set key below horizontal box Left reverse maxrows 2
set grid
set xlabel 'cross-track error m (lower is better)'
set xrange [15.5:19]
set multiplot layout 1,2 title "Hand-over rules on the validation scenarios (5 pairs): every one on the ranges' front, below it or just beside it; none in the goal's corner (shaded)"
set ylabel 'progress % (higher is better)'
set yrange [96.1:97.3]
set object 1 rect from graph 0, first 97 to first 17, graph 1 fc rgb '#b8e0b8' fs solid 0.5 noborder behind
plot data using 4:($3 * family('range')) with linespoints lw 2 pt 13 ps 1.3 lc rgb '#444444' \
       title 'near member within 10-50 m, then everywhere', \
     for [i=1:3] data using 4:($3 * family(word(families, i))) \
       with points pt (int(word(points, i))) ps 1.3 title title_of(i)
unset object 1
set ylabel 'collisions % (lower is better)'
set yrange [2:4]
set object 2 rect from graph 0, graph 0 to first 17, first 3 fc rgb '#b8e0b8' fs solid 0.5 noborder behind
plot data using 4:($5 * family('range')) with linespoints lw 2 pt 13 ps 1.3 lc rgb '#444444' \
       title 'near member within 10-50 m, then everywhere', \
     for [i=1:3] data using 4:($5 * family(word(families, i))) \
       with points pt (int(word(points, i))) ps 1.3 title title_of(i)
unset multiplot
