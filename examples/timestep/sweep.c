/* sweep.c - the rigid-sphere/rigid-wall test of Han (2004), Box 3.1, swept
 * over the time step factor lambda for the linear (m = 1), Hertz (1.5) and
 * Winkler (2) laws, as Fig. 3.15.
 *
 *   sweep LMAX N     writes "lambda ratio_m1 ratio_m1.5 ratio_m2" for
 *                    lambda = LMAX i / N, i = 1..N, on stdout
 *
 * The ratio v_exit / v0 does not depend on the mass, k_n or v0 (Ch. 3.7.2),
 * so all three are 1.
 */
#include <stdio.h>
#include <stdlib.h>

#include "contact/law.h"

int main(int argc, char **argv)
{
	if (argc != 3) {
		fprintf(stderr, "usage: sweep LMAX N\n");
		return 2;
	}
	double lmax = atof(argv[1]);
	int n = atoi(argv[2]);
	if (!(lmax > 0 && lmax <= 1) || n < 1) {
		fprintf(stderr, "sweep: expected 0 < LMAX <= 1 and N >= 1\n");
		return 2;
	}
	printf("# Box 3.1 rigid sphere/wall test (Han 2004, Fig. 3.15): v_exit/v0 against lambda\n");
	printf("# lambda\tlinear_m1\thertz_m1.5\twinkler_m2\n");
	for (int i = 1; i <= n; i++) {
		double l = lmax * i / n;
		printf("%.6f\t%.8f\t%.8f\t%.8f\n", l, dem_dt_wall_test(1, 1, 1, 1, l, NULL, NULL),
		       dem_dt_wall_test(1.5, 1, 1, 1, l, NULL, NULL), dem_dt_wall_test(2, 1, 1, 1, l, NULL, NULL));
	}
	return ferror(stdout) || fclose(stdout) ? 4 : 0;
}
