# saturation.gp - the Almen saturation curve: arc height against exposure
# (passes of 4 shots on the tile), the fitted curve h = a (1 - exp(-b n)) and its saturation point
# (T, 0.9 a) with the doubled exposure 2T, and the three-parameter curve
# a (1 - exp(-b n^c)) (SAE J2597's forms, fitted by demfit).  Variables
# (saturation.sh's fit.txt and the
# command line): curve, fit_a, fit_b, T, intensity, fit3_a, fit3_b, fit3_c,
# T3, out
set terminal pngcairo size 900,560 font ",11" enhanced
set output out
set title sprintf("Almen A strip, saturation curve: T = %.1f, intensity %.3f mm (%.4f in A)", T, intensity, intensity / 25.4)
set xlabel "exposure (passes of 4 shots on the 1.68 mm tile)"
set ylabel "arc height over 31.75 mm (mm)"
set grid
set key bottom right
set xrange [0:*]
set yrange [0:*]
set offsets 0, 0, graph 0.1, 0
h(n) = fit_a * (1 - exp(-fit_b * n))
set arrow 1 from T, 0 to T, intensity nohead dt 2 lc 7
set arrow 2 from 2 * T, 0 to 2 * T, h(2 * T) nohead dt 3 lc 7
set label 1 sprintf(" T: h = %.3f mm", intensity) at T, intensity point pt 9 ps 2 lc 7 left offset 0.5, -1
set label 2 "2T: +10 %" at 2 * T, h(2 * T) right offset -0.5, 1
set samples 400
h3(n) = fit3_a * (1 - exp(-fit3_b * n**fit3_c))
plot curve using 1:3 with points pt 7 ps 1 lc 1 title "arc height after release (demform)", \
     h(x) with lines lw 2 lc 2 title sprintf("fit a (1 - e^{-b n}): a = %.3f mm, b = %.3f", fit_a, fit_b), \
     h3(x) with lines lw 1.5 dt 2 lc 4 title sprintf("fit a (1 - e^{-b n^c}): c = %.3f%s", fit3_c, T3 > 0 ? sprintf(", T = %.1f", T3) : ", no T")
