/* par.c - par.h on one process: the build without MPI.  Every operation
 * leaves its data as it is (this rank's values are everybody's). */
#include "par/par.h"

#include <stdlib.h>

struct dem_par {
	int size;
};

int dem_par_mpi(void)
{
	return 0;
}

int dem_par_init(dem_par_t **p, int *argc, char ***argv, dem_error_t *e)
{
	(void)argc, (void)argv;
	if (!(*p = malloc(sizeof **p)))
		return dem_error_nomem(e, "process group");
	(*p)->size = 1;
	return DEM_OK;
}

void dem_par_finalize(dem_par_t *p)
{
	free(p);
}

void dem_par_abort(const dem_par_t *p, int code)
{
	(void)p;
	exit(code);
}

int dem_par_rank(const dem_par_t *p)
{
	(void)p;
	return 0;
}

int dem_par_size(const dem_par_t *p)
{
	(void)p;
	return 1;
}

void dem_par_halo_sum(dem_par_t *p, double *lo, double *hi, size_t n, double *buf)
{
	(void)p, (void)lo, (void)hi, (void)n, (void)buf;
}

void dem_par_sum_ordered(dem_par_t *p, double *v, size_t n, double *buf)
{
	(void)p, (void)v, (void)n, (void)buf;
}

double dem_par_min(dem_par_t *p, double v)
{
	(void)p;
	return v;
}

int dem_par_max_int(dem_par_t *p, int v)
{
	(void)p;
	return v;
}

void dem_par_gather(dem_par_t *p, void *buf, size_t unit, const size_t *off)
{
	(void)p, (void)buf, (void)unit, (void)off;
}

void dem_par_bcast(dem_par_t *p, void *buf, size_t n, int root)
{
	(void)p, (void)buf, (void)n, (void)root;
}

void dem_par_barrier(dem_par_t *p)
{
	(void)p;
}
