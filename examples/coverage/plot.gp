# plot.gp - the plastic coverage against the Avrami law: the means over the
# seeds of report.sh's curve.txt after every impact, against the exposure
# N pi a^2 / A (impacts times one footprint's share of the impact area).
# Variables (the command line): curve (curve.txt), out (the png), seeds.
set terminal pngcairo size 900,560 font ",11" enhanced
set output out
set title sprintf("Plastic coverage of random impacts, mean of %d seeds (Al 5052, D = 0.28 mm, 50 m/s)", seeds)
set xlabel "exposure N {/Symbol p} a^2 / A"
set ylabel "covered share of the profile region"
set grid
set key bottom right
set xrange [0:*]
set yrange [0:1.02]
set y2label "FE - Avrami (percentage points)"
set y2tics
set y2range [-4:12]
set ytics nomirror
plot curve using 2:3 with lines lw 2 lc 7 title "Avrami 1 - exp(-N {/Symbol p} a^2/A)", \
     curve using 2:5 with lines lw 1.5 dt 2 lc 2 title "discs of radius a on the same impacts", \
     curve using 2:6 with lines lw 2 lc 1 title "FE plastic coverage (demprofile)", \
     curve using 2:(100 * ($6 - $3)) axes x1y2 with lines lw 1 lc 4 title "FE - Avrami (right axis)", \
     curve using 2:(100 * ($6 - $5 + $4 - $3)) axes x1y2 with lines lw 1 dt 3 lc 4 title "FE - discs + E[discs] - Avrami (right axis)"
