# profiles.gp - the residual stress sxx and the plastic strain of the sample
# block against depth, pass by pass, one panel a velocity (Fig. 8.5 (a),
# (b), (e), (f) of the thesis).  Variables from the command line:
#   runs  the run directories (each with profile.txt), space separated
#   vels  their velocities (m/s)
#   last  the last pass number
#   out   the PNG
n = words(runs)
set terminal pngcairo size 650*n,1000 font ",11" enhanced
set output out
set multiplot layout 2,n title "Residual profiles of the sample block (mean over the impacted region), after each pass"
set xlabel "depth below the peened face (mm)"
set grid
set xzeroaxis lt -1 lw 1
set xrange [0:1.5]
# at most 8 curves a panel: every step-th pass and the last
step = (last + 1) / 8 > 1 ? (last + 1) / 8 : 1
set palette defined (0 "#2166ac", 1 "#b2182b")
unset colorbox
do for [i=1:n] {
	set title sprintf("v = %s m/s: {/Symbol s}_{xx}", word(vels, i))
	set ylabel "{/Symbol s}_{xx} (MPa)"
	set key bottom right
	plot for [p=step-1:last:step] word(runs, i)."/profile.txt" using ($2*1000):($1 == p ? $3/1e6 : 1/0) \
	         with lines lw 1.5 lc palette frac (p + 0.0) / last title sprintf("pass %d", p + 1)
}
do for [i=1:n] {
	set title sprintf("v = %s m/s: effective plastic strain", word(vels, i))
	set ylabel "{/Symbol e}_p"
	set key top right
	plot for [p=step-1:last:step] word(runs, i)."/profile.txt" using ($2*1000):($1 == p ? $15 : 1/0) \
	         with lines lw 1.5 lc palette frac (p + 0.0) / last title sprintf("pass %d", p + 1)
}
unset multiplot
