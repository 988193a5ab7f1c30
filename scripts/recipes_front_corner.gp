# Draws docs/recipes_front_corner.png from docs/recipes_front.csv: a close-up of the goal's corner
# of docs/recipes_front.png, where the labels crowd. Progress against cross-track error for the
# rows with a corner_label (our agents near the goal; means over 5 or 10 seeds or ensembles, 95 %
# intervals in grey), numbered, with the list of their means beside; filled where the collisions
# are at most 3 %, so a filled point in the shaded area meets all three of issue 16's bounds.
# Run from the repository's root: gnuplot scripts/recipes_front_corner.gp
set terminal pngcairo size 1500,800 enhanced font 'DejaVu Sans,11'
set output 'docs/recipes_front_corner.png'
set datafile separator ','
set datafile missing ''
data = 'docs/recipes_front.csv'
drawn(y) = strcol(15) eq '-' ? NaN : y
within_collision_bound(y) = $10 <= 3.0 ? drawn(y) : NaN
over_collision_bound(y) = $10 > 3.0 ? drawn(y) : NaN
# The drawn rows' numbers, in file order: counted again by each plot that shows them.
number = 0
next_number(y) = drawn(y) == drawn(y) ? sprintf('%d', number = number + 1) : ''
set multiplot title "The goal's corner: our agents near it (filled: collisions at most 3 %; shaded: progress at least 97 % and cross-track error at most 17 m)"
set size 0.6, 0.95
set origin 0, 0
set xlabel 'cross-track error m (lower is better)'
set ylabel 'progress % (higher is better)'
set xrange [16.2:19.6]
set yrange [96.4:97.6]
set grid
set key bottom right box
set object 1 rect from graph 0, first 97 to first 17, graph 1 fc rgb '#b8e0b8' fs solid 0.5 noborder behind
plot data skip 7 using 7:(drawn($4)):8:9:5:6 with xyerrorbars lc rgb '#d0d0d0' pt -1 notitle, \
     data skip 7 using 7:(within_collision_bound($4)) with points pt 7 ps 1.6 lc rgb '#1b7837' \
       title 'collisions at most 3 %', \
     data skip 7 using 7:(over_collision_bound($4)) with points pt 6 ps 1.6 lw 2 lc rgb '#b2182b' \
       title 'collisions over 3 %', \
     number = 0, \
     data skip 7 using 7:(drawn($4)):(next_number($4)) with labels offset 0.7,0.5 left font ',10' notitle
unset object 1
# The list: one line per drawn row, top to bottom in the same order.
set size 0.4, 0.95
set origin 0.6, 0
unset xlabel
unset ylabel
unset grid
unset border
unset tics
unset key
set xrange [0:1]
set yrange [-26:0]
set label 1 "critic: a privileged critic's agent; relieved: the memory takes the helm when the\nvessel stalls; rescued: the paper recipe's baseline after a second stall; near: at the\nhelm within that range of an obstacle, the memory elsewhere" at first 0, first -24.6 left font ',9'
# A drawn row's line is the number its label is about to take (the y column is read first).
line_of(y) = drawn(y) == drawn(y) ? -(number + 1) : NaN
plot number = 0, \
     data skip 7 using (0):(line_of($4)):(sprintf('%s  %s: %.1f %%, %.1f m, %.1f %%', \
       next_number($4), strcol(15), $4, $7, $10)) with labels left font ',10' notitle
unset label 1
unset multiplot
