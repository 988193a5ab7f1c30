# Draws docs/seed_front.png from docs/seed_front.csv (scripts/seed_front.py): every agent of the
# studies run on this machine, one point per training seed, the distilled students (one network
# learnt from three, scripts/distill_policy.py; their training steps not recorded, so their
# "steps" are empty), those students fine-tuned by PPO (steps empty too, told apart by their
# configuration's name: finetuned* or distilled_narrow*) and the authors' three agents, collisions against progress and against
# cross-track error, with issue 16's goal (collisions <= 3 %, progress >= 97 %, cross-track
# error <= 17 m) shaded.
# Run from the repository's root: gnuplot scripts/seed_front.gp
set terminal pngcairo size 1500,640 enhanced font 'DejaVu Sans,11'
set output 'docs/seed_front.png'
set datafile separator ','
data = 'docs/seed_front.csv'
# columns: 1 agent, 5 kind, 6 steps, 7 progress, 8 cte, 9 collisions
short(y) = (strcol(5) eq 'ours' && strcol(6) ne '' && column(6) < 10000000) ? y : NaN
long(y) = (strcol(5) eq 'ours' && strcol(6) ne '' && column(6) >= 10000000) ? y : NaN
is_finetune = "strstrt(strcol(3), 'finetuned') == 1 || strstrt(strcol(3), 'distilled_narrow') == 1"
distilled(y) = (strcol(5) eq 'ours' && strcol(6) eq '' && !(@is_finetune)) ? y : NaN
finetuned(y) = (strcol(5) eq 'ours' && strcol(6) eq '' && (@is_finetune)) ? y : NaN
authors(y) = strcol(5) eq 'authors' ? y : NaN
set key top right box opaque
set grid
set xlabel 'collisions % (lower is better)'
set xrange [0:16]
set multiplot layout 1,2 title "Every agent, seed by seed, on the same 1,000 scenarios: two reach the goal (shaded), a distilled student and a fine-tuned one"
set ylabel 'progress % (higher is better)'
set yrange [88:98.5]
set object 1 rect from graph 0, first 97 to first 3, graph 1 fc rgb '#b8e0b8' behind
plot data skip 1 using 9:(short($7)) with points pt 6 ps 0.9 lc rgb '#7f9fbf' title 'ours, 3,000,000 steps', \
     data skip 1 using 9:(long($7)) with points pt 7 ps 0.7 lc rgb '#1f5f9f' title 'ours, 15,000,000 steps', \
     data skip 1 using 9:(distilled($7)) with points pt 5 ps 0.8 lc rgb '#1b9e77' title 'ours, distilled: one network from three', \
     data skip 1 using 9:(finetuned($7)) with points pt 13 ps 0.9 lc rgb '#7570b3' title 'ours, distilled, then fine-tuned by PPO', \
     data skip 1 using 9:(authors($7)) with points pt 9 ps 2.0 lc rgb '#d95f02' title "the authors' agents"
unset object 1
set ylabel 'cross-track error m (lower is better)'
set yrange [12:34]
set object 2 rect from graph 0, graph 0 to first 3, first 17 fc rgb '#b8e0b8' behind
plot data skip 1 using 9:(short($8)) with points pt 6 ps 0.9 lc rgb '#7f9fbf' title 'ours, 3,000,000 steps', \
     data skip 1 using 9:(long($8)) with points pt 7 ps 0.7 lc rgb '#1f5f9f' title 'ours, 15,000,000 steps', \
     data skip 1 using 9:(distilled($8)) with points pt 5 ps 0.8 lc rgb '#1b9e77' title 'ours, distilled: one network from three', \
     data skip 1 using 9:(finetuned($8)) with points pt 13 ps 0.9 lc rgb '#7570b3' title 'ours, distilled, then fine-tuned by PPO', \
     data skip 1 using 9:(authors($8)) with points pt 9 ps 2.0 lc rgb '#d95f02' title "the authors' agents"
unset multiplot
