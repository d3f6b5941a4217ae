/* sweep.c - the rigid-sphere/rigid-wall test of Han (2004), Box 3.1, swept
 * over the time step factor lambda for the linear (m = 1), Hertz (1.5) and
 * Winkler (2) laws, as Fig. 3.15, with the thesis scheme and with the
 * separation correction of lib/contact/model.h (beyond the thesis).
 *
 *   sweep LMAX N     writes, for lambda = LMAX i / N, i = 1..N, on stdout:
 *                    lambda, v_exit/v0 of the thesis scheme for m = 1, 1.5,
 *                    2 (dem_dt_wall_test), then with the correction
 *                    (dem_contact_wall_test, the same step of Eq. 3.81)
 *
 * The ratio v_exit / v0 does not depend on the mass, k_n or v0 (Ch. 3.7.2),
 * so all three are 1.
 */
#include <stdio.h>
#include <stdlib.h>

#include "contact/law.h"
#include "contact/model.h"

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
	const double ms[3] = { 1, 1.5, 2 };
	dem_contact_model_t cm[3];
	for (int j = 0; j < 3; j++) {
		dem_contact_param_t p = { .law = { .m = ms[j], .coef = 1 }, .sepfix = DEM_SEPFIX_ON };
		dem_error_t e = { 0 };
		if (dem_contact_model_init(&cm[j], &p, &e)) {
			fprintf(stderr, "sweep: %s\n", e.msg);
			return 3;
		}
	}
	printf("# Box 3.1 rigid sphere/wall test (Han 2004, Fig. 3.15): v_exit/v0 against lambda;\n");
	printf("# columns 2-4 the thesis scheme, 5-7 with the separation correction (lib/contact/model.h)\n");
	printf("# lambda\tlinear_m1\thertz_m1.5\twinkler_m2\tfix_linear\tfix_hertz\tfix_winkler\n");
	for (int i = 1; i <= n; i++) {
		double l = lmax * i / n, fix[3];
		for (int j = 0; j < 3; j++) {
			dem_wall_run_t r;
			dem_error_t e = { 0 };
			if (dem_contact_wall_test(&cm[j], 1, 1, 1, l, DEM_WALL_STEP_IMPACT, &r, &e)) {
				fprintf(stderr, "sweep: lambda %g: %s\n", l, e.msg);
				return 3;
			}
			fix[j] = r.ratio;
		}
		printf("%.6f\t%.8f\t%.8f\t%.8f\t%.8f\t%.8f\t%.8f\n", l, dem_dt_wall_test(1, 1, 1, 1, l, NULL, NULL),
		       dem_dt_wall_test(1.5, 1, 1, 1, l, NULL, NULL), dem_dt_wall_test(2, 1, 1, 1, l, NULL, NULL),
		       fix[0], fix[1], fix[2]);
	}
	return ferror(stdout) || fclose(stdout) ? 4 : 0;
}
