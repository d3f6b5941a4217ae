# profile.gp - the residual stress through the depth (Figs. 8.5 and 8.8 of
# the thesis, for this coarse run).  Variables from the command line:
#   prof    demprofile's profile stream (all passes)
#   centre  demform's --centre table (the strip's centre after forming)
#   last    the last pass number
#   out     the PNG
set terminal pngcairo size 1300,560 font ",11" enhanced
set output out
set multiplot layout 1,2 title "Residual stress against depth: the peened sample block (demshot | demprofile) and the formed strip (demform)" noenhanced
set xlabel "depth below the peened face (mm)"
set ylabel "stress (MPa)"
set grid
set key bottom right
set xzeroaxis lt -1 lw 1

# left: the peened layer, pass by pass (sxx solid, syy dashed)
set title "sample block: mean over the impacted region, after each pass"
set xrange [0:1.5]
plot for [p=0:last] prof using ($2*1000):($1 == p ? $3/1e6 : 1/0) \
         with linespoints lw 1.5 pt 7 ps 0.5 lc p+1 title sprintf("pass %d  {/Symbol s}_{xx}", p), \
     for [p=0:last] prof using ($2*1000):($1 == p ? $4/1e6 : 1/0) \
         with lines dt 2 lw 1.5 lc p+1 title sprintf("pass %d  {/Symbol s}_{yy}", p)

# right: the whole thickness, before forming (the profile of the last pass,
# imposed as initial stress) and after (redistributed, at the strip centre)
set title sprintf("through the 4 mm thickness: pass %d profile and the formed strip", last)
set xrange [0:4]
set key bottom right
plot prof using ($2*1000):($1 == last ? $3/1e6 : 1/0) with linespoints lw 1.5 pt 7 ps 0.5 lc 1 \
         title "{/Symbol s}_{xx}, sample block (initial stress)", \
     prof using ($2*1000):($1 == last ? $4/1e6 : 1/0) with lines dt 2 lw 1.5 lc 1 \
         title "{/Symbol s}_{yy}, sample block", \
     centre using ($1*1000):($2/1e6) with linespoints lw 1.5 pt 5 ps 0.4 lc 7 \
         title "{/Symbol s}_{xx}, formed strip centre (redistributed)", \
     centre using ($1*1000):($3/1e6) with lines dt 2 lw 1.5 lc 7 \
         title "{/Symbol s}_{yy}, formed strip centre"
unset multiplot
