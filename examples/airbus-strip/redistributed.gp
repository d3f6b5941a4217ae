# redistributed.gp - sxx through the 4 mm thickness: the last pass's profile
# (the initial stress) and the redistributed stress at the centre of the
# formed strip, both velocities (Fig. 8.8 of the thesis).  Variables:
#   runs  the run directories (profile.txt, centre.txt), space separated
#   vels  their velocities (m/s)
#   last  the last pass number
#   out   the PNG
set terminal pngcairo size 900,600 font ",11" enhanced
set output out
set title sprintf("{/Symbol s}_{xx} through the thickness after pass %d: profile imposed, and redistributed in the free strip", last + 1)
set xlabel "depth below the peened face (mm)"
set ylabel "{/Symbol s}_{xx} (MPa)"
set grid
set key bottom right
set xzeroaxis lt -1 lw 1
set xrange [0:4]
plot for [i=1:words(runs)] word(runs, i)."/profile.txt" using ($2*1000):($1 == last ? $3/1e6 : 1/0) \
         with lines dt 2 lw 1.5 lc i title sprintf("v = %s m/s, sample block (imposed)", word(vels, i)), \
     for [i=1:words(runs)] word(runs, i)."/centre.txt" using ($1*1000):($2/1e6) \
         with linespoints lw 2 pt 7 ps 0.5 lc i title sprintf("v = %s m/s, formed strip centre", word(vels, i))
