/* curve.c - the uniaxial stress-strain response of a scene's material
 * (lib/fe/material.c through dem_mat_uniaxial): monotonic tension, then
 * symmetric strain cycles, for plots of each law of the material library.
 *
 *   curve SCENE.yaml [AMPLITUDE [CYCLES [RATE]]]
 *
 * Writes TSV rows "eps  sigma_MPa  ep  phase" on stdout: phase 0 is the
 * monotonic loading to 4 AMPLITUDE (default 0.02), phase k >= 1 the k-th
 * cycle of the fresh material between +-AMPLITUDE (default 5 cycles); RATE
 * (1/s, default 0: static) is the axial strain rate, for the rate laws.
 */
#include <stdio.h>
#include <stdlib.h>

#include "fe/fescene.h"
#include "fe/material.h"
#include "io/scene.h"

int main(int argc, char **argv)
{
	if (argc < 2 || argc > 5) {
		fprintf(stderr, "usage: curve SCENE.yaml [AMPLITUDE [CYCLES [RATE]]]\n");
		return 2;
	}
	double amp = argc > 2 ? atof(argv[2]) : 0.02, rate = argc > 4 ? atof(argv[4]) : 0;
	int ncyc = argc > 3 ? atoi(argv[3]) : 5;
	dem_scene_t *s;
	dem_mat_t m;
	dem_error_t e = { 0 };
	if (dem_scene_load(&s, argv[1], &e) || dem_scene_material(s, 0, &m, &e)) {
		fprintf(stderr, "curve: %s\n", e.msg);
		return 1;
	}
	const int nstep = 400;   /* per amplitude */
	double de = amp / nstep, dt = rate > 0 ? de / rate : 0;
	printf("# eps\tsigma_MPa\tep\tphase\n");
	for (int phase = 0; phase <= (ncyc > 0 ? 1 : 0); phase++) {
		double eps[6] = { 0 }, sig[6] = { 0 }, ep = 0, kin[6 * DEM_MAT_NKIN] = { 0 };
		int n = phase == 0 ? 4 * nstep : 4 * nstep * ncyc;
		printf("0\t0\t0\t%d\n", phase);
		for (int i = 0; i < n; i++) {
			int q = i % (4 * nstep);
			double d = phase == 0 || q < nstep || q >= 3 * nstep ? de : -de;
			if (dem_mat_uniaxial(&m, d, dt, eps, sig, &ep, kin)) {
				fprintf(stderr, "curve: the uniaxial iteration failed at eps %g\n", eps[0]);
				return 3;
			}
			printf("%.6g\t%.6g\t%.6g\t%d\n", eps[0], sig[0] / 1e6, ep,
			       phase == 0 ? 0 : 1 + i / (4 * nstep));
		}
	}
	dem_mat_free(&m);
	dem_scene_free(s);
	return 0;
}
