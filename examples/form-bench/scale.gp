# scale.gp - demform's wall time and memory against the equations
# (gnuplot -e "tsv='out/scale.tsv'; out='out/scale.png'" scale.gp)
set terminal pngcairo size 900,560 font ",11"
set output out
set logscale xy
set xlabel "equations"
set ylabel "time (s)"
set y2label "peak memory (GB)"
set logscale y2
set ytics nomirror
set y2tics
set key top left
set grid
set datafile separator "\t"
v(b, t) = (strcol(2) eq b && $3 == t)
plot tsv using 4:(v("serial", 1) ? $10 : 1/0) with points pt 7 title "wall, sequential OpenBLAS, 1 thread", \
     tsv using 4:(v("pthread", 2) ? $10 : 1/0) with points pt 5 title "wall, OpenBLAS pthreads, 2 threads", \
     tsv using 4:(v("openmp", 2) ? $10 : 1/0) with points pt 9 title "wall, OpenBLAS OpenMP, 2 threads", \
     tsv using 4:(v("serial", 1) ? $8 : 1/0) with points pt 6 title "factor, sequential, 1 thread", \
     tsv using 4:(v("serial", 1) ? $12 / 1024 : 1/0) axes x1y2 with points pt 4 title "memory (right), sequential"
