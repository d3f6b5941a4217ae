/* par.c - par.h.  Built with DEM_MPI (make MPI=1, or make check's MPI
 * link; OpenMPI's flags from mpicc --showme): the ranks of a duplicate of
 * MPI_COMM_WORLD, so that the toolkit's messages never meet another
 * library's.  Without it: one process, every operation leaving its data as
 * it is (this rank's values are everybody's).  The one file any compiler
 * builds with the plain flags; only the MPI half needs mpi.h. */
#include "par/par.h"

#ifdef DEM_MPI

#include <limits.h>
#include <mpi.h>
#include <stdlib.h>
#include <string.h>

struct dem_par {
	MPI_Comm comm;
	int rank, size;
	int *cnt, *dsp;    /* size each: the gather's counts and displacements */
};

int dem_par_mpi(void)
{
	return 1;
}

int dem_par_init(dem_par_t **out, int *argc, char ***argv, dem_error_t *e)
{
	int provided, init;
	*out = NULL;
	MPI_Initialized(&init);
	if (!init && MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
		return dem_error_set(e, DEM_EIO, "MPI: cannot start");
	dem_par_t *p = calloc(1, sizeof *p);
	if (!p)
		return dem_error_nomem(e, "process group");
	MPI_Comm_dup(MPI_COMM_WORLD, &p->comm);
	MPI_Comm_rank(p->comm, &p->rank);
	MPI_Comm_size(p->comm, &p->size);
	p->cnt = malloc((size_t)p->size * sizeof *p->cnt);
	p->dsp = malloc((size_t)p->size * sizeof *p->dsp);
	if (!p->cnt || !p->dsp) {
		free(p->cnt), free(p->dsp), free(p);
		return dem_error_nomem(e, "process group");
	}
	*out = p;
	return DEM_OK;
}

void dem_par_finalize(dem_par_t *p)
{
	if (!p)
		return;
	MPI_Comm_free(&p->comm);
	free(p->cnt), free(p->dsp), free(p);
	MPI_Finalize();
}

void dem_par_abort(const dem_par_t *p, int code)
{
	if (p && p->size > 1)
		MPI_Abort(p->comm, code);
	exit(code);
}

int dem_par_rank(const dem_par_t *p)
{
	return p ? p->rank : 0;
}

int dem_par_size(const dem_par_t *p)
{
	return p ? p->size : 1;
}

/* n doubles as an int count (a plane of nodes or a record: far below) */
static int icount(const dem_par_t *p, size_t n)
{
	if (n > INT_MAX)
		MPI_Abort(p->comm, 4);
	return (int)n;
}

void dem_par_halo_sum(dem_par_t *p, double *lo, double *hi, size_t n, double *buf)
{
	if (!p || p->size == 1 || n == 0)
		return;
	int up = p->rank + 1 < p->size ? p->rank + 1 : MPI_PROC_NULL;
	int down = p->rank > 0 ? p->rank - 1 : MPI_PROC_NULL;
	int c = icount(p, n);
	double *from_below = buf, *from_above = buf + n;
	/* up the chain, then down it: each rank pairs with both neighbours */
	MPI_Sendrecv(up != MPI_PROC_NULL ? hi : buf, up != MPI_PROC_NULL ? c : 0, MPI_DOUBLE, up, 221,
		     from_below, down != MPI_PROC_NULL ? c : 0, MPI_DOUBLE, down, 221, p->comm,
		     MPI_STATUS_IGNORE);
	MPI_Sendrecv(down != MPI_PROC_NULL ? lo : buf, down != MPI_PROC_NULL ? c : 0, MPI_DOUBLE, down, 222,
		     from_above, up != MPI_PROC_NULL ? c : 0, MPI_DOUBLE, up, 222, p->comm,
		     MPI_STATUS_IGNORE);
	/* the lower rank's value first, on both sides */
	if (down != MPI_PROC_NULL)
		for (size_t i = 0; i < n; i++)
			lo[i] = from_below[i] + lo[i];
	if (up != MPI_PROC_NULL)
		for (size_t i = 0; i < n; i++)
			hi[i] = hi[i] + from_above[i];
}

void dem_par_sum_ordered(dem_par_t *p, double *v, size_t n, double *buf)
{
	if (!p || p->size == 1 || n == 0)
		return;
	int c = icount(p, n);
	MPI_Allgather(v, c, MPI_DOUBLE, buf, c, MPI_DOUBLE, p->comm);
	for (size_t i = 0; i < n; i++) {
		double s = buf[i];
		for (int r = 1; r < p->size; r++)
			s += buf[(size_t)r * n + i];
		v[i] = s;
	}
}

double dem_par_min(dem_par_t *p, double v)
{
	if (!p || p->size == 1)
		return v;
	double m;
	MPI_Allreduce(&v, &m, 1, MPI_DOUBLE, MPI_MIN, p->comm);
	return m;
}

int dem_par_max_int(dem_par_t *p, int v)
{
	if (!p || p->size == 1)
		return v;
	int m;
	MPI_Allreduce(&v, &m, 1, MPI_INT, MPI_MAX, p->comm);
	return m;
}

void dem_par_gather(dem_par_t *p, void *buf, size_t unit, const size_t *off)
{
	if (!p || p->size == 1 || unit == 0)
		return;
	MPI_Datatype t;
	MPI_Type_contiguous(icount(p, unit), MPI_BYTE, &t);
	MPI_Type_commit(&t);
	for (int r = 0; r < p->size; r++) {
		p->cnt[r] = icount(p, off[r + 1] - off[r]);
		p->dsp[r] = icount(p, off[r]);
	}
	MPI_Allgatherv(MPI_IN_PLACE, 0, MPI_DATATYPE_NULL, buf, p->cnt, p->dsp, t, p->comm);
	MPI_Type_free(&t);
}

void dem_par_bcast(dem_par_t *p, void *buf, size_t n, int root)
{
	if (!p || p->size == 1)
		return;
	char *b = buf;
	while (n > 0) {
		size_t k = n < (size_t)1 << 30 ? n : (size_t)1 << 30;
		MPI_Bcast(b, (int)k, MPI_BYTE, root, p->comm);
		b += k, n -= k;
	}
}

void dem_par_barrier(dem_par_t *p)
{
	if (p && p->size > 1)
		MPI_Barrier(p->comm);
}

#else /* one process */

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

#endif /* DEM_MPI */
