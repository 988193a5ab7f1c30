# Draws docs/recipes_front.png from docs/recipes_front.csv: every recipe measured (mean over 5
# training seeds, 95 % intervals), twenty-two ensembles of our runs, two of them distilled into one
# network each, and the authors' agents, collisions against progress and against
# cross-track error, with the issue's goal (collisions <= 3 %, progress >= 97 %, cross-track
# error <= 17 m) shaded. Run from the repository's root: gnuplot scripts/recipes_front.gp
set terminal pngcairo size 1500,700 enhanced font 'DejaVu Sans,11'
set output 'docs/recipes_front.png'
set datafile separator ','
set datafile missing ''
data = 'docs/recipes_front.csv'
group(name) = (strcol(2) eq name) ? 1 : NaN
# Beside cross-track error the distilled students sit among the ensembles' labels: theirs goes
# below and to the left there.
apart = 'distilled'
not_in_group(name) = (strcol(2) eq name) ? NaN : 1
groups = "3M 10M 15M authors ensembles distilled"
title_of(i) = i == 1 ? '3,000,000 steps' : i == 2 ? '10,000,000 steps' : \
              i == 3 ? '15,000,000-25,000,000 steps' : i == 4 ? "the authors' agents" : \
              i == 5 ? 'ensembles of our runs' : 'one network distilled from three'
points = "5 9 7 3 11 13"
set key below horizontal box
set grid
set xlabel 'collisions % (lower is better)'
set xrange [0:12]
set style fill transparent solid 0.35 noborder
set multiplot layout 1,2 title "Every recipe on the same 1,000 scenarios. Inside the goal (shaded) on all three at once: the rescued helmsmen, the privileged critic near\nwithin 30 m (chosen on validation scenarios) or 40 m, the memory elsewhere, rescued, and the critic at lambda 0.91 or among vessels at 175 m (not chosen)"
set ylabel 'progress % (higher is better)'
set yrange [90:98]
set object 1 rect from graph 0, first 97 to first 3, graph 1 fc rgb '#b8e0b8' behind
plot for [i=1:6] data skip 7 using 10:($4 * group(word(groups, i))):11:12:5:6 \
       with xyerrorbars pt (int(word(points, i))) ps 1.3 title title_of(i), \
     data skip 7 using 10:4:14 with labels offset 0.8,0.6 left font ',9' noenhanced notitle
unset object 1
set ylabel 'cross-track error m (lower is better)'
set yrange [12:25]
set object 2 rect from graph 0, graph 0 to first 3, first 17 fc rgb '#b8e0b8' behind
plot for [i=1:6] data skip 7 using 10:($7 * group(word(groups, i))):11:12:8:9 \
       with xyerrorbars pt (int(word(points, i))) ps 1.3 title title_of(i), \
     data skip 7 using 10:($7 * not_in_group(apart)):14 with labels offset 0.8,0.6 left font ',9' noenhanced notitle, \
     data skip 7 using 10:($7 * group(apart)):14 with labels offset -0.8,-0.7 right font ',9' noenhanced notitle
unset multiplot
