# laws.gp - the saturation curves of the material laws (make laws): the
# arc height of the strip against the exposure, one curve per law and
# velocity.  Variables from the command line:
#   files   curve.txt files (exposure in column 1, arc height in column 3),
#           the laws of the first velocity, then the same of the second
#   labels  their labels, in the same order, words joined by '_'
#   out     the PNG
set terminal pngcairo size 960,600 font ",11" enhanced
set output out
set title "Arc height of the 150 x 50 x 4 mm strip: the material laws (quick preset)"
set xlabel "exposure (the thesis's passes: 16 shots on the 5.6 x 5.6 mm area)"
set ylabel "arc height (mm)"
set grid
set key top left noenhanced
set yrange [0:*]
set xrange [0:33]
set label 1 "thesis, 32 passes: 2.2 (36 m/s)" at 18,2.2 left
set label 2 "2.45 (46.5 m/s)" at 18,2.45 left
set arrow 1 from 31,2.2 to 32.6,2.2 nohead lw 3 lc "black"
set arrow 2 from 31,2.45 to 32.6,2.45 nohead lw 3 lc "black"
# the files come velocity by velocity, the same laws in the same order:
# a colour per law, solid for the first velocity, dashed for the second
n = words(files) / 2
plot for [i=1:words(files)] word(files, i) using 1:3 \
         with linespoints lw 2 pt 7 ps 0.6 lc (i - 1) % n + 1 dt 1 + (i - 1) / n \
         title system("echo ".word(labels, i)." | tr _ ' '")
