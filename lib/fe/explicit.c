/* explicit.c - explicit dynamics of the finite element block (see
 * explicit.h).
 *
 * Layout.  Node data are arrays of 3 doubles per node (x, v, internal and
 * external forces).  The one-point element state is kept in blocks of NB
 * consecutive elements with the element innermost (sig[6][NB], ep[NB],
 * Qs[12][NB]), the layout of the hex8 and material batch kernels; a block
 * never straddles two slabs, so the last block of a slab may be short and
 * is padded with copies of its last element, whose forces are dropped (the
 * padding lanes see the same inputs as the element they copy and keep the
 * same state).  The full-integration state is per element: two batches of
 * four Gauss points, sig[2][6][NB], ep[2][NB].
 *
 * Runs.  In a block of NB elements along a row of the mesh (run[block]),
 * element e has the nodes of element 0 plus e: the node data of the block
 * are read as NB consecutive nodes (whole vectors, transposed in
 * registers), and the forces of each pair of nodes I, I + 1 along the row
 * are summed in registers and added to the NB + 1 nodes they reach, once
 * each (the order of the additions at a node is fixed by the mesh, not by
 * the threads).  Other blocks gather and scatter element by element.  The
 * element state of the block PF ahead is prefetched.
 *
 * Slabs.  Elements are numbered i fastest, then j, then k, so a slab of
 * whole k-layers is a contiguous range of elements, and so is a band of
 * rows of one layer.  A mesh of many layers is cut into slabs of whole
 * layers; a thin one (fewer than MINLAYER layers) into bands of rows of
 * each layer, so that each phase below has tasks enough to keep every
 * thread busy (a 10-layer block had 5 slabs to a phase: with 2 threads,
 * one thread waited a third of each phase).  Slab (k, b) shares nodes only
 * with slabs k +- 1 and b +- 1, so the slabs of one colour (k mod 2,
 * b mod 2) add their forces at once, the four colours one after another.
 * The cut depends on the mesh only, never on the threads: a node's forces
 * are summed in the same order whatever their number.
 */
#include "fe/explicit.h"

#include <math.h>
#include <omp.h>
#include <stdlib.h>
#include <string.h>

#include "core/cost.h"
#include "fe/cdiff.h"
#include "fe/ckpt.h"
#include "fe/hex8.h"
#include "fe/simd.h"

#define NCHUNK 64     /* node chunks of the node loop (fixed: see header) */
#define MAXSLAB 32    /* slabs of element layers */
#define MINLAYER 16   /* fewer layers: each layer cut in bands of rows */
#define MINTASK 8     /* slabs to a colour, at least, in a banded mesh */
#ifndef PF
#define PF 4 /* blocks ahead to prefetch */
#endif
#define PAR_MIN 20000 /* fewer elements than this: one thread by default */

#if DEM_HEX8_NB != 4
#error "the gather of slab_1pt assumes 4 lanes"
#endif
typedef double vec4 __attribute__((vector_size(4 * sizeof(double))));

typedef long long lvec4 __attribute__((vector_size(4 * sizeof(double))));
/* Lanes i0..i3 of the 8-lane concatenation (a, b), the indices constant:
 * __builtin_shufflevector in clang and GCC >= 12, __builtin_shuffle with a
 * mask vector in older GCC */
#if defined(__clang__) || (defined(__GNUC__) && __GNUC__ >= 12)
#define SHUF4(a, b, i0, i1, i2, i3) __builtin_shufflevector(a, b, i0, i1, i2, i3)
#else
#define SHUF4(a, b, i0, i1, i2, i3) __builtin_shuffle(a, b, (lvec4){ i0, i1, i2, i3 })
#endif
/* an unaligned vector in memory: one whole-vector load or store (GCC
 * splits a memcpy of 32 bytes in halves, which a whole-vector access then
 * fails to forward from) */
typedef double uvec4 __attribute__((vector_size(4 * sizeof(double)), aligned(8), may_alias));

enum { E_INT, E_PL, E_HG, E_NPL, E_N };          /* element-loop sums */

typedef struct slab {
	size_t e0, e1;     /* elements [e0, e1) */
	size_t b0, nb;     /* one-point blocks [b0, b0 + nb) */
	int k0, k1;        /* element layers [k0, k1) */
	int j0, j1;        /* rows [j0, j1) of each */
	double sum[E_N];   /* this step's element sums */
	double dt2;        /* least squared step estimate (large strain) */
	size_t bad;        /* 1 + first bad element, 0 if none */
} slab_t;

typedef struct pload {
	size_t nq, nt;
	uint32_t *quad;
	double *t, *p;
} pload_t;

struct dem_fe {
	const dem_mesh_t *mesh;
	const dem_mat_t *mat;
	dem_fe_opts_t o;
	size_t nn, ne;
	double *x, *v, *fi, *fx, *mass;
	const uint8_t *fix;   /* the node loop's constraints: mesh->fix, or
			       * fixown with the periodic slaves held */
	/* periodic ties (mesh->tie): a slave's mass and forces go to its
	 * master, and the node loop leaves it alone (mass 0, all held); after
	 * the node loop it takes the master's velocity and position plus
	 * toff, the reference offset */
	size_t ntie;
	uint8_t *fixown;
	double *pmass, *toff; /* pmass: the mass of a node's tied set */
	/* element state */
	size_t nblk;
	double *sig, *ep, *Qs, *eps, *kdt;
	double *kin;          /* back-stresses, [6 nkin][NB] per batch (NULL: none) */
	double *syc;          /* each point's static flow stress as last seen by the
			       * general return, beside ep (dem_mat_update_batch;
			       * NULL: a law with a closed-form return, or
			       * back-stresses); not checkpointed: reset to the
			       * floor of the curve on load */
	int nh;               /* dem_mat_nhist */
	size_t npt;           /* points in syc (0: none) */
	uint8_t *run;         /* one-point block whose element e has the nodes
			       * of element 0 plus e (a run along a row) */
	int hg;               /* hourglass control on */
	int nthr;             /* threads */
	int nslab, nband;     /* slabs; bands of rows to a layer group */
	slab_t *slab;         /* layer group major, band minor: element order */
	int *slab_of_k;       /* layer group of layer k */
	int *band_of_j;       /* band of row j */
	int *order;           /* slabs by colour, colour c from order[coff[c]] */
	int coff[5];
	double chunk[NCHUNK][DEM_CD_N];
	/* loads */
	pload_t *pl;
	int npl;
	dem_fe_load_fn hook;
	void *hctx;
	size_t hlo, hhi;      /* the nodes the hook may load: [hlo, hhi) */
	size_t plo, phi;      /* the nodes of the pressure loads */
	int ext;              /* external forces this step */
	size_t xlo, xhi;      /* ... on nodes [xlo, xhi) alone: the node loop
			       * reads and clears fx there only */
	/* time */
	double t, dt_prev, dt_stable;
	long steps;
	/* energies */
	dem_cd_work_t w;
	dem_fe_energy_t en;
	/* failure */
	int failed;
	dem_error_t fail;
	/* counters */
	double cycles, nplastic, elem_s, node_s, comm_s;
	/* ranks (explicit.h, "Ranks"): this one runs slabs [s0, s1), updates
	 * nodes [nu0, nu1) and owns [noff[rank], noff[rank + 1]) for the sums
	 * and dem_fe_sync; soff, noff, boff: per rank, size + 1 offsets of
	 * slabs, nodes and element state (one-point blocks, or elements) */
	dem_par_t *par;
	int rank, nrank, s0, s1;
	size_t plane, nu0, nu1;
	size_t *soff, *noff, *boff;
	double *pbuf;         /* scratch of the halo */
	double *grec;         /* the ranks' records (ranks_exchange), rank r's
			       * at goff[r] */
	size_t *goff;
	double comm;          /* bytes sent in the last step */
};

/* a slab's record for the other ranks: its sums, dt2 and bad */
#define SREC (E_N + 2)

void dem_fe_opts_default(dem_fe_opts_t *o)
{
	memset(o, 0, sizeof *o);
	o->rule = DEM_FE_1PT;
	o->large = 0;
	o->dt_factor = 0.9;
	o->damping = 0;
	o->hg_stiff = 0.1;
	o->hg_visc = 0;
	o->hg_tangent = 1;
}

double dem_fe_damping_alpha(const dem_mat_t *m, double xi, double H)
{
	double cs = sqrt(m->G / m->rho);
	return 2 * xi * 3.14159265358979323846 * cs / (2 * H);
}

/* ---- Set-up --------------------------------------------------------------- */

/* Largest |c_k|^2 of the mid-section modes k = 1..3: |c_k| / 2 is the area
 * of the element's mid-section normal to natural axis k (exact for a
 * parallelepiped). */
static double midsection2(const double c[8][3])
{
	double m = 0;
	for (int k = 1; k <= 3; k++) {
		double s = c[k][0] * c[k][0] + c[k][1] * c[k][1] + c[k][2] * c[k][2];
		m = s > m ? s : m;
	}
	return m;
}

static void elem_ijk(const dem_mesh_t *m, size_t el, int *i, int *j, int *k)
{
	*i = (int)(el % (size_t)m->nx);
	*j = (int)(el / (size_t)m->nx % (size_t)m->ny);
	*k = (int)(el / ((size_t)m->nx * (size_t)m->ny));
}

/* block and lane of a one-point element */
static void elem_lane(const dem_fe_t *fe, size_t el, size_t *blk, int *lane)
{
	size_t nx = (size_t)fe->mesh->nx, ny = (size_t)fe->mesh->ny;
	const slab_t *s = &fe->slab[fe->slab_of_k[el / (nx * ny)] * fe->nband + fe->band_of_j[el / nx % ny]];
	size_t loc = el - s->e0;
	*blk = s->b0 + loc / NB;
	*lane = (int)(loc % NB);
}

void dem_fe_free(dem_fe_t *fe)
{
	if (!fe)
		return;
	free(fe->x), free(fe->v), free(fe->fi), free(fe->fx), free(fe->mass);
	free(fe->fixown), free(fe->toff);
	if (fe->pmass != fe->mass)
		free(fe->pmass);
	free(fe->sig), free(fe->ep), free(fe->Qs), free(fe->eps), free(fe->kdt);
	free(fe->kin), free(fe->syc);
	free(fe->run);
	free(fe->slab), free(fe->slab_of_k), free(fe->band_of_j), free(fe->order);
	free(fe->soff), free(fe->noff), free(fe->boff), free(fe->pbuf), free(fe->grec), free(fe->goff);
	for (int i = 0; i < fe->npl; i++)
		free(fe->pl[i].quad), free(fe->pl[i].t), free(fe->pl[i].p);
	free(fe->pl);
	free(fe);
}

/* The periodic ties: the masters take their slaves' masses, the slaves
 * are held in the node loop and keep the offset of the reference mesh. */
static int tie_setup(dem_fe_t *fe)
{
	const dem_mesh_t *m = fe->mesh;
	size_t nt = m->ntie;
	fe->ntie = nt;
	fe->fixown = malloc(fe->nn);
	fe->pmass = malloc(fe->nn * sizeof *fe->pmass);
	fe->toff = malloc(3 * nt * sizeof *fe->toff);
	if (!fe->fixown || !fe->pmass || !fe->toff)
		return -1;
	memcpy(fe->fixown, m->fix, fe->nn);
	for (size_t t = 0; t < nt; t++) {
		size_t s = m->tie[2 * t], ms = m->tie[2 * t + 1];
		fe->mass[ms] += fe->mass[s];
		fe->fixown[s] = DEM_FIX_X | DEM_FIX_Y | DEM_FIX_Z;
		for (int c = 0; c < 3; c++)
			fe->toff[3 * t + c] = m->X[3 * s + c] - m->X[3 * ms + c];
	}
	memcpy(fe->pmass, fe->mass, fe->nn * sizeof *fe->pmass);
	for (size_t t = 0; t < nt; t++) {
		size_t s = m->tie[2 * t];
		fe->pmass[s] = fe->mass[m->tie[2 * t + 1]];
		fe->mass[s] = 0;
	}
	fe->fix = fe->fixown;
	return 0;
}

/* Before the node loop: the slaves' forces onto their masters. */
static void tie_gather(dem_fe_t *fe)
{
	const uint32_t *tie = fe->mesh->tie;
	for (size_t t = 0; t < fe->ntie; t++) {
		size_t s = 3 * (size_t)tie[2 * t], ms = 3 * (size_t)tie[2 * t + 1];
		if (tie[2 * t] < fe->nu0 || tie[2 * t] >= fe->nu1)
			continue;   /* another rank's plane */
		for (int c = 0; c < 3; c++) {
			fe->fi[ms + c] += fe->fi[s + c];
			fe->fi[s + c] = 0;
			if (fe->ext) {
				fe->fx[ms + c] += fe->fx[s + c];
				fe->fx[s + c] = 0;
			}
		}
	}
}

/* After the node loop: the slaves move with their masters. */
static void tie_scatter(dem_fe_t *fe)
{
	const uint32_t *tie = fe->mesh->tie;
	for (size_t t = 0; t < fe->ntie; t++) {
		size_t s = 3 * (size_t)tie[2 * t], ms = 3 * (size_t)tie[2 * t + 1];
		if (tie[2 * t] < fe->nu0 || tie[2 * t] >= fe->nu1)
			continue;
		for (int c = 0; c < 3; c++) {
			fe->v[s + c] = fe->v[ms + c];
			fe->x[s + c] = fe->x[ms + c] + fe->toff[3 * t + c];
		}
	}
}

/* Every point's flow-stress record at the floor of the curve, which is
 * never above sigma_y(ep): the first general return of each point sets it. */
static void syc_reset(dem_fe_t *fe)
{
	for (size_t i = 0; i < fe->npt; i++)
		fe->syc[i] = fe->mat->sy_floor;
}

/* The ranks' shares (explicit.h, "Ranks"): contiguous ranges of slabs,
 * bottom to top; each rank owns the node planes from the lowest of its
 * slabs up to, not including, the next rank's (the top rank: to the top).
 * Returns DEM_EINPUT with e set, or -1 out of memory. */
static int ranks_setup(dem_fe_t *fe, dem_error_t *e)
{
	const dem_mesh_t *m = fe->mesh;
	dem_par_t *p = fe->o.par;
	int P = dem_par_size(p), nb = fe->nband, ns = fe->nslab / nb;  /* layer groups */
	fe->par = p;
	fe->nrank = P;
	fe->rank = dem_par_rank(p);
	fe->plane = (size_t)(m->nx + 1) * (size_t)(m->ny + 1);
	if (P > ns)
		return dem_error_set(e, DEM_EINPUT, "explicit: %d ranks for %d slabs of element layers "
				     "(a rank needs one at least: the mesh has %d layers)", P, ns, m->nz);
	fe->soff = malloc((size_t)(P + 1) * sizeof *fe->soff);
	fe->noff = malloc((size_t)(P + 1) * sizeof *fe->noff);
	fe->boff = malloc((size_t)(P + 1) * sizeof *fe->boff);
	fe->goff = malloc((size_t)(P + 1) * sizeof *fe->goff);
	fe->pbuf = malloc(2 * 3 * fe->plane * sizeof *fe->pbuf);
	if (!fe->soff || !fe->noff || !fe->boff || !fe->goff || !fe->pbuf)
		return -1;
	int full = fe->o.rule == DEM_FE_FULL;
	for (int r = 0; r <= P; r++) {
		int s = (int)((long)r * ns / P) * nb;  /* whole layer groups: planes between ranks */
		fe->soff[r] = (size_t)s;
		fe->noff[r] = r == P ? fe->nn : (size_t)fe->slab[s].k0 * fe->plane;
		fe->boff[r] = r == P ? (full ? fe->ne : fe->nblk) : full ? fe->slab[s].e0 : fe->slab[s].b0;
	}
	/* the records of ranks_exchange */
	fe->goff[0] = 0;
	for (int r = 0; r < P; r++)
		fe->goff[r + 1] = fe->goff[r] + (fe->soff[r + 1] - fe->soff[r]) * SREC +
				  DEM_CD_N + (r == P - 1 ? 6 * fe->plane : 0);
	if (!(fe->grec = malloc(fe->goff[P] * sizeof *fe->grec)))
		return -1;
	fe->s0 = (int)fe->soff[fe->rank];
	fe->s1 = (int)fe->soff[fe->rank + 1];
	fe->nu0 = fe->noff[fe->rank];
	fe->nu1 = (size_t)(fe->slab[fe->s1 - 1].k1 + 1) * fe->plane;
	if (P > 1)
		for (size_t t = 0; t < m->ntie; t++)
			if (m->tie[2 * t] / fe->plane != m->tie[2 * t + 1] / fe->plane)
				return dem_error_set(e, DEM_EINPUT, "explicit: with several ranks, periodic ties "
						     "must tie nodes of one x-y plane (tie %zu does not)", t);
	return 0;
}

int dem_fe_create(dem_fe_t **out, const dem_mesh_t *mesh, const dem_mat_t *mat,
		  const dem_fe_opts_t *o, dem_error_t *e)
{
	*out = NULL;
	if (o->rule != DEM_FE_1PT && o->rule != DEM_FE_FULL)
		return dem_error_set(e, DEM_EINPUT, "explicit: unknown integration rule %d", (int)o->rule);
	if (!(o->dt_factor > 0 && o->dt_factor <= 1))
		return dem_error_set(e, DEM_EINPUT, "explicit: time step factor must be in (0, 1], got %g",
				     o->dt_factor);
	if (!(o->damping >= 0) || !isfinite(o->damping))
		return dem_error_set(e, DEM_EINPUT, "explicit: damping must be >= 0, got %g", o->damping);
	if (!(o->hg_stiff >= 0) || !(o->hg_visc >= 0) || !isfinite(o->hg_stiff + o->hg_visc))
		return dem_error_set(e, DEM_EINPUT, "explicit: hourglass coefficients must be >= 0");
	if (o->threads < 0)
		return dem_error_set(e, DEM_EINPUT, "explicit: threads must be >= 0, got %d", o->threads);
	if (!(mat->rho > 0))
		return dem_error_set(e, DEM_EINPUT, "explicit: the material needs a density");
	if (mesh->ne == 0 || mesh->nx < 1 || mesh->ny < 1 || mesh->nz < 1)
		return dem_error_set(e, DEM_EINPUT, "explicit: empty mesh");

	dem_fe_t *fe = calloc(1, sizeof *fe);
	if (!fe)
		return dem_error_nomem(e, "explicit model");
	fe->mesh = mesh;
	fe->mat = mat;
	fe->o = *o;
	fe->nn = mesh->nn;
	fe->ne = mesh->ne;
	fe->nh = dem_mat_nhist(mat);
	fe->hg = o->rule == DEM_FE_1PT && (o->hg_stiff > 0 || o->hg_visc > 0);
	size_t nn = fe->nn, ne = fe->ne;
	fe->nthr = o->threads > 0 ? o->threads : ne >= PAR_MIN ? omp_get_max_threads() : 1;

	/* slabs: groups of whole layers, or in a thin mesh bands of rows of
	 * each layer, enough for MINTASK slabs to a colour; more ranks than
	 * MAXSLAB: a group each (the serial slabs, and those of up to MAXSLAB
	 * ranks, do not depend on the ranks) */
	int nz = mesh->nz, ny = mesh->ny;
	size_t nx = (size_t)mesh->nx;
	int np = dem_par_size(o->par), ms = np > MAXSLAB ? np : MAXSLAB;
	int ngrp = nz < ms ? nz : ms, nband = 1;
	if (nz < MINLAYER) {
		int half = (nz + 1) / 2;
		nband = 2 * ((MINTASK + half - 1) / half);
		nband = nband < ny ? nband : ny;
	}
	fe->nband = nband;
	fe->nslab = ngrp * nband;
	fe->slab = calloc((size_t)fe->nslab, sizeof *fe->slab);
	fe->slab_of_k = malloc((size_t)nz * sizeof *fe->slab_of_k);
	fe->band_of_j = malloc((size_t)ny * sizeof *fe->band_of_j);
	fe->order = malloc((size_t)fe->nslab * sizeof *fe->order);
	if (!fe->slab || !fe->slab_of_k || !fe->band_of_j || !fe->order)
		goto nomem;
	size_t nblk = 0;
	for (int g = 0; g < ngrp; g++)
		for (int b = 0; b < nband; b++) {
			slab_t *sl = &fe->slab[g * nband + b];
			sl->k0 = (int)((long)g * nz / ngrp);
			sl->k1 = (int)((long)(g + 1) * nz / ngrp);
			sl->j0 = (int)((long)b * ny / nband);
			sl->j1 = (int)((long)(b + 1) * ny / nband);
			/* one layer to a group when banded: the rows contiguous */
			sl->e0 = nx * ((size_t)sl->j0 + (size_t)ny * (size_t)sl->k0);
			sl->e1 = nband > 1 ? nx * ((size_t)sl->j1 + (size_t)ny * (size_t)sl->k0)
					   : nx * (size_t)ny * (size_t)sl->k1;
			sl->b0 = nblk;
			sl->nb = (sl->e1 - sl->e0 + NB - 1) / NB;
			nblk += sl->nb;
			for (int k = sl->k0; k < sl->k1; k++)
				fe->slab_of_k[k] = g;
			for (int j = sl->j0; j < sl->j1; j++)
				fe->band_of_j[j] = b;
		}
	fe->nblk = nblk;
	int no = 0;
	for (int c = 0; c < 4; c++) {
		fe->coff[c] = no;
		for (int s = 0; s < fe->nslab; s++)
			if ((s / nband % 2) == c / 2 && (s % nband % 2) == c % 2)
				fe->order[no++] = s;
	}
	fe->coff[4] = no;
	int rrc = ranks_setup(fe, e);
	if (rrc < 0)
		goto nomem;
	if (rrc) {
		dem_fe_free(fe);
		return rrc;
	}

	fe->x = malloc(3 * nn * sizeof *fe->x);
	fe->v = calloc(3 * nn, sizeof *fe->v);
	fe->fi = calloc(3 * nn, sizeof *fe->fi);
	fe->fx = calloc(3 * nn, sizeof *fe->fx);
	fe->mass = calloc(nn, sizeof *fe->mass);
	if (!fe->x || !fe->v || !fe->fi || !fe->fx || !fe->mass)
		goto nomem;
	memcpy(fe->x, mesh->X, 3 * nn * sizeof *fe->x);
	if (o->rule == DEM_FE_1PT) {
		fe->sig = calloc(nblk * 6 * NB, sizeof *fe->sig);
		fe->ep = calloc(nblk * NB, sizeof *fe->ep);
		if (fe->nh)
			fe->kin = calloc(nblk * (size_t)fe->nh * NB, sizeof *fe->kin);
		fe->Qs = calloc(nblk * 12 * NB, sizeof *fe->Qs);
		fe->run = calloc(nblk, sizeof *fe->run);
		if (o->large) {
			fe->eps = calloc(nblk * 6 * NB, sizeof *fe->eps);
			fe->kdt = calloc(nblk * NB, sizeof *fe->kdt);
		}
	} else {
		fe->sig = calloc(ne * 2 * 6 * NB, sizeof *fe->sig);
		fe->ep = calloc(ne * 2 * NB, sizeof *fe->ep);
		if (fe->nh)
			fe->kin = calloc(ne * 2 * (size_t)fe->nh * NB, sizeof *fe->kin);
		if (o->large) {
			fe->eps = calloc(ne * 6, sizeof *fe->eps);
			fe->kdt = calloc(ne, sizeof *fe->kdt);
		}
	}
	if ((mat->flags & DEM_MAT_GENERAL) && !fe->nh) {
		fe->npt = o->rule == DEM_FE_1PT ? nblk * NB : ne * 2 * NB;
		if ((fe->syc = malloc(fe->npt * sizeof *fe->syc)))
			syc_reset(fe);
	}
	if (!fe->sig || !fe->ep || (fe->nh && !fe->kin) || (o->rule == DEM_FE_1PT && (!fe->Qs || !fe->run)) ||
	    (o->large && (!fe->eps || !fe->kdt)) || (fe->npt && !fe->syc))
		goto nomem;

	/* masses, element steps and their shape factors */
	double dtmin = INFINITY;
	for (size_t el = 0; el < ne; el++) {
		double xe[24], me[8], dte;
		dem_hex8_1pt_t g;
		dem_mesh_gather(mesh, el, NULL, xe);
		if (dem_hex8_lumped_mass(xe, mat->rho, me) || dem_hex8_1pt_geom(xe, &g) ||
		    dem_hex8_dt_crit(xe, mat->wave, &dte)) {
			int i, j, k;
			elem_ijk(mesh, el, &i, &j, &k);
			dem_fe_free(fe);
			return dem_error_set(e, DEM_EINPUT, "explicit: element %zu (i, j, k = %d, %d, %d) "
					     "of the mesh is inverted or degenerate", el, i, j, k);
		}
		for (int I = 0; I < 8; I++)
			fe->mass[mesh->hex[8 * el + I]] += me[I];
		dtmin = dte < dtmin ? dte : dtmin;
		if (o->large) {
			/* dt^2 = kdt (V / |c|max)^2, exact at the start */
			double r = g.vol * g.vol / midsection2(g.c);
			if (o->rule == DEM_FE_1PT) {
				size_t b;
				int l;
				elem_lane(fe, el, &b, &l);
				fe->kdt[b * NB + l] = dte * dte / r;
			} else {
				fe->kdt[el] = dte * dte / r;
			}
		}
	}
	/* blocks of NB elements in a row: their node numbers step by one */
	if (o->rule == DEM_FE_1PT)
		for (int s = 0; s < fe->nslab; s++) {
			const slab_t *sl = &fe->slab[s];
			for (size_t bl = 0; bl < sl->nb; bl++) {
				size_t el0 = sl->e0 + bl * NB;
				int ok = sl->e1 - el0 >= NB;
				const uint32_t *h0 = mesh->hex + 8 * el0;
				ok = ok && h0[1] == h0[0] + 1 && h0[2] == h0[3] + 1 &&
				     h0[5] == h0[4] + 1 && h0[6] == h0[7] + 1;
				for (int l = 1; ok && l < NB; l++)
					for (int I = 0; I < 8; I++)
						ok &= mesh->hex[8 * (el0 + (size_t)l) + I] ==
						      mesh->hex[8 * el0 + I] + (uint32_t)l;
				fe->run[sl->b0 + bl] = (uint8_t)ok;
			}
		}
	/* padding lanes copy their block's last element */
	if (o->rule == DEM_FE_1PT && o->large)
		for (int s = 0; s < fe->nslab; s++) {
			slab_t *sl = &fe->slab[s];
			size_t n = sl->e1 - sl->e0, b = sl->b0 + sl->nb - 1;
			for (size_t l = n - (sl->nb - 1) * NB; l < NB; l++)
				fe->kdt[b * NB + l] = fe->kdt[b * NB + (n - 1) % NB];
		}
	fe->fix = mesh->fix;
	fe->pmass = fe->mass;
	fe->plo = nn, fe->phi = 0;
	if (mesh->ntie > 0 && tie_setup(fe))
		goto nomem;
	fe->dt_stable = o->dt_factor * dtmin;
	*out = fe;
	return DEM_OK;
nomem:
	dem_fe_free(fe);
	return dem_error_nomem(e, "explicit model");
}

/* ---- Loads ---------------------------------------------------------------- */

int dem_fe_add_pressure(dem_fe_t *fe, size_t nquad, const uint32_t *quad,
			size_t nt, const double *t, const double *p, dem_error_t *e)
{
	if (dem_cd_table_check(nt, t, p, e))
		return e->code;
	for (size_t q = 0; q < 4 * nquad; q++) {
		if (quad[q] >= fe->nn)
			return dem_error_set(e, DEM_EINPUT, "pressure: face %zu names node %u of %zu",
					     q / 4, quad[q], fe->nn);
		/* explicit.h, "Ranks": only the top surface is current on every rank */
		if (fe->nrank > 1 && fe->o.large && quad[q] / fe->plane != (size_t)fe->mesh->nz)
			return dem_error_set(e, DEM_EINPUT, "pressure: face %zu is not on the top surface: "
					     "with several ranks, a large-strain pressure must be", q / 4);
	}
	pload_t *pl = realloc(fe->pl, (size_t)(fe->npl + 1) * sizeof *pl);
	if (!pl)
		return dem_error_nomem(e, "pressure load");
	fe->pl = pl;
	pl = &fe->pl[fe->npl];
	memset(pl, 0, sizeof *pl);
	pl->quad = malloc((4 * nquad + 1) * sizeof *pl->quad);
	pl->t = malloc(nt * sizeof *pl->t);
	pl->p = malloc(nt * sizeof *pl->p);
	if (!pl->quad || !pl->t || !pl->p) {
		free(pl->quad), free(pl->t), free(pl->p);
		return dem_error_nomem(e, "pressure load");
	}
	memcpy(pl->quad, quad, 4 * nquad * sizeof *quad);
	memcpy(pl->t, t, nt * sizeof *t);
	memcpy(pl->p, p, nt * sizeof *p);
	pl->nq = nquad;
	pl->nt = nt;
	for (size_t q = 0; q < 4 * nquad; q++) {
		fe->plo = quad[q] < fe->plo ? quad[q] : fe->plo;
		fe->phi = quad[q] + (size_t)1 > fe->phi ? quad[q] + (size_t)1 : fe->phi;
	}
	fe->npl++;
	return DEM_OK;
}

size_t dem_fe_top_quads(const dem_mesh_t *m, double x0, double x1, double y0,
			double y1, uint32_t *quad)
{
	size_t n = 0;
	for (int j = 0; j < m->ny; j++)
		for (int i = 0; i < m->nx; i++) {
			double xc = 0.5 * (m->gx[i] + m->gx[i + 1]);
			double yc = 0.5 * (m->gy[j] + m->gy[j + 1]);
			if (xc < x0 || xc > x1 || yc < y0 || yc > y1)
				continue;
			if (quad) {
				/* counter-clockwise seen from +z, outside the top */
				uint32_t *q = quad + 4 * n;
				q[0] = (uint32_t)dem_mesh_node(m, i, j, m->nz);
				q[1] = (uint32_t)dem_mesh_node(m, i + 1, j, m->nz);
				q[2] = (uint32_t)dem_mesh_node(m, i + 1, j + 1, m->nz);
				q[3] = (uint32_t)dem_mesh_node(m, i, j + 1, m->nz);
			}
			n++;
		}
	return n;
}

void dem_fe_set_load(dem_fe_t *fe, dem_fe_load_fn fn, void *ctx)
{
	fe->hook = fn;
	fe->hctx = ctx;
	fe->hlo = 0, fe->hhi = fe->nn;
}

void dem_fe_set_load_nodes(dem_fe_t *fe, size_t n0, size_t n1)
{
	fe->hlo = n0 < fe->nn ? n0 : fe->nn;
	fe->hhi = n1 < fe->nn ? n1 : fe->nn;
}

static void apply_pressure(dem_fe_t *fe, const pload_t *pl, double t)
{
	double p = dem_cd_history(pl->nt, pl->t, pl->p, t);
	if (p == 0)
		return;
	const double *x = fe->o.large ? fe->x : fe->mesh->X;
	for (size_t q = 0; q < pl->nq; q++) {
		const uint32_t *n = pl->quad + 4 * q;
		double d1[3], d2[3];
		for (int c = 0; c < 3; c++) {
			d1[c] = x[3 * (size_t)n[2] + c] - x[3 * (size_t)n[0] + c];
			d2[c] = x[3 * (size_t)n[3] + c] - x[3 * (size_t)n[1] + c];
		}
		/* area vector (d1 x d2) / 2; a quarter to each node, inward */
		double s = -0.125 * p;
		double f[3] = { s * (d1[1] * d2[2] - d1[2] * d2[1]),
				s * (d1[2] * d2[0] - d1[0] * d2[2]),
				s * (d1[0] * d2[1] - d1[1] * d2[0]) };
		for (int I = 0; I < 4; I++)
			for (int c = 0; c < 3; c++)
				fe->fx[3 * (size_t)n[I] + c] += f[c];
	}
}

/* The node and element loops: -O3 with fused multiply-adds, as the
 * kernels. */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC push_options
#pragma GCC optimize("O3", "fp-contract=fast")
#endif

/* ---- Node loop ------------------------------------------------------------ */

/* vector blend: lanes of a where the mask m is set, else of b (a macro:
 * a function returning a vector would change the ABI where AVX is off) */
#define BLEND4(m, a, b) ((vec4)(((m) & (lvec4)(a)) | (~(m) & (lvec4)(b))))

/* Nodes [n0, n1): the velocity and coordinate update of each degree of
 * freedom, and the energy sums.  Four nodes at a time as 12 degrees of
 * freedom in three vectors (the per-degree arithmetic of the scalar tail,
 * expression for expression: the same updates bit for bit; the sums are
 * kept per lane, so their rounding depends on the grouping, the updates'
 * does not). */
static inline __attribute__((always_inline)) void node_range(dem_fe_t *fe, const dem_cd_coef_t *c, size_t n0, size_t n1,
			      double sum[DEM_CD_N], const int ext)
{
	const uint8_t *fix = fe->fix;
	double *restrict x = fe->x, *restrict v = fe->v, *restrict fi = fe->fi;
	double *restrict fx = fe->fx;
	const double *restrict mass = fe->mass;
	vec4 T4 = { 0 }, wxa4 = { 0 }, wxb4 = { 0 }, wda4 = { 0 }, wdb4 = { 0 };
	const vec4 zero = { 0 };
	/* the fixed bit of each lane's degree of freedom (node-major x, y, z) */
	const lvec4 bit[3] = { { 1, 2, 4, 1 }, { 2, 4, 1, 2 }, { 4, 1, 2, 4 } };
	size_t n = n0;
	for (; n + 4 <= n1; n += 4) {
		vec4 mv = *(const uvec4 *)(mass + n), rmv = c->cf / mv;
		vec4 M[3] = { SHUF4(mv, mv, 0, 0, 0, 1), SHUF4(mv, mv, 1, 1, 2, 2), SHUF4(mv, mv, 2, 3, 3, 3) };
		vec4 RM[3] = { SHUF4(rmv, rmv, 0, 0, 0, 1), SHUF4(rmv, rmv, 1, 1, 2, 2),
			       SHUF4(rmv, rmv, 2, 3, 3, 3) };
		long long f0 = fix[n], f1 = fix[n + 1], f2 = fix[n + 2], f3 = fix[n + 3];
		lvec4 FB[3] = { { f0, f0, f0, f1 }, { f1, f1, f2, f2 }, { f2, f3, f3, f3 } };
		for (int q = 0; q < 3; q++) {
			size_t d = 3 * n + 4 * (size_t)q;
			lvec4 fixed = (FB[q] & bit[q]) != 0;
			vec4 m = M[q], rm = RM[q];
			vec4 fext = zero;
			if (ext)
				fext = *(const uvec4 *)(fx + d);
			vec4 fid = *(const uvec4 *)(fi + d);
			vec4 F = fext - fid;
			vec4 vm = *(const uvec4 *)(v + d);
			vec4 vp = BLEND4(fixed, vm, (c->co * vm + rm * F) * c->rden);
			vec4 vn = c->w1 * vp + c->w0 * vm;
			vec4 dua = c->dtp * vm, dub = c->dt * vp;
			vec4 fd = c->alpha * m * vn;
			vec4 fa = BLEND4(fixed, m * (vp - vm) * c->rdth + fd + fid, fext);
			T4 += m * (c->k0 * vm + c->k1 * vp) * vp;
			wda4 += fd * dua;
			wdb4 += fd * dub;
			wxa4 += fa * dua;
			wxb4 += fa * dub;
			*(uvec4 *)(v + d) = vp;
			*(uvec4 *)(x + d) = *(const uvec4 *)(x + d) + dub;
			*(uvec4 *)(fi + d) = zero;
			if (ext)
				*(uvec4 *)(fx + d) = zero;
		}
	}
	double T = 0, wxa = 0, wxb = 0, wda = 0, wdb = 0;
	for (int l = 0; l < 4; l++) {
		T += T4[l], wxa += wxa4[l], wxb += wxb4[l];
		wda += wda4[l], wdb += wdb4[l];
	}
	for (; n < n1; n++) {
		double m = mass[n], rm = c->cf / m;
		unsigned fb = fix[n];
		for (int k = 0; k < 3; k++) {
			size_t d = 3 * n + k;
			double fext = ext ? fx[d] : 0;
			double F = fext - fi[d];
			double vm = v[d];
			int fixed = fb >> k & 1;
			double vp = fixed ? vm : (c->co * vm + rm * F) * c->rden;
			double vn = c->w1 * vp + c->w0 * vm;
			double dua = c->dtp * vm, dub = c->dt * vp;
			double fd = c->alpha * m * vn;
			/* the force the loads apply: on a constrained dof, the
			 * reaction too (mass times acceleration, damping and
			 * internal force minus the loads) */
			double fa = fixed ? m * (vp - vm) * c->rdth + fd + fi[d] : fext;
			T += m * (c->k0 * vm + c->k1 * vp) * vp;
			wda += fd * dua;
			wdb += fd * dub;
			wxa += fa * dua;
			wxb += fa * dub;
			v[d] = vp;
			x[d] += dub;
			fi[d] = 0;
			if (ext)
				fx[d] = 0;
		}
	}
	sum[DEM_CD_T] = 0.5 * T;
	sum[DEM_CD_WXA] = 0.5 * wxa;
	sum[DEM_CD_WXB] = 0.5 * wxb;
	sum[DEM_CD_WDA] = 0.5 * wda;
	sum[DEM_CD_WDB] = 0.5 * wdb;
}

static inline __attribute__((always_inline)) void node_part(dem_fe_t *fe, const dem_cd_coef_t *c, size_t n0,
							     size_t n1, double sum[DEM_CD_N])
{
	if (n0 >= n1) {
		memset(sum, 0, DEM_CD_N * sizeof *sum);
		return;
	}
	if (fe->ext && n0 < fe->xhi && fe->xlo < n1)
		node_range(fe, c, n0, n1, sum, 1);
	else
		node_range(fe, c, n0, n1, sum, 0);
}

SIMD_CLONES
static void node_chunk(dem_fe_t *fe, const dem_cd_coef_t *c, int ch)
{
	size_t n0 = fe->nn * (size_t)ch / NCHUNK, n1 = fe->nn * (size_t)(ch + 1) / NCHUNK;
	if (fe->nrank > 1) {
		/* the nodes this rank updates: its own, summed, then the plane
		 * it shares with the rank above, whose sums are that rank's */
		size_t o1 = fe->noff[fe->rank + 1];
		double junk[DEM_CD_N];
		node_part(fe, c, n0 > fe->nu0 ? n0 : fe->nu0, n1 < o1 ? n1 : o1, fe->chunk[ch]);
		node_part(fe, c, n0 > o1 ? n0 : o1, n1 < fe->nu1 ? n1 : fe->nu1, junk);
		return;
	}
	node_part(fe, c, n0, n1, fe->chunk[ch]);
}

/* ---- Element loops ---------------------------------------------------------- */

/* Jaumann rotation of a strain with engineering shears over dt (the
 * rotation of dem_mat_jaumann, on the tensor eps_ij = gamma_ij / 2). */
static inline void rotate_strain(double e[6], double a, double b, double c)
{
	double e0 = e[0], e1 = e[1], e2 = e[2], g3 = e[3], g4 = e[4], g5 = e[5];
	e[0] += a * g3 - c * g5;
	e[1] += b * g4 - a * g3;
	e[2] += c * g5 - b * g4;
	e[3] += 2 * a * (e1 - e0) - c * g4 + b * g5;
	e[4] += 2 * b * (e2 - e1) - a * g5 + c * g3;
	e[5] += 2 * c * (e0 - e2) - b * g3 + a * g4;
}

/* 4 nodes' x, y, z (12 doubles, node-major) to x[4], y[4], z[4] in place,
 * and back */
static inline void aos_soa(vec4 a[3])
{
	vec4 x = SHUF4(a[0], a[1], 0, 3, 6, 7), y = SHUF4(a[0], a[1], 1, 4, 7, 4);
	vec4 z = SHUF4(a[0], a[1], 2, 5, 5, 5);
	a[0] = SHUF4(x, a[2], 0, 1, 2, 5);
	a[1] = SHUF4(y, a[2], 0, 1, 2, 6);
	a[2] = SHUF4(z, a[2], 0, 1, 4, 7);
}

static inline void soa_aos(vec4 a[3])
{
	vec4 t = SHUF4(a[0], a[1], 0, 4, 1, 5), u = SHUF4(a[1], a[2], 1, 5, 2, 6);
	vec4 w = SHUF4(a[0], a[1], 3, 7, 2, 6);
	vec4 o0 = SHUF4(t, a[2], 0, 1, 4, 2), o1 = SHUF4(u, a[0], 0, 1, 6, 2);
	vec4 o2 = SHUF4(w, a[2], 6, 0, 1, 7);
	a[0] = o0, a[1] = o1, a[2] = o2;
}

static inline __attribute__((always_inline)) void slab_1pt(dem_fe_t *fe, slab_t *s, double dt, const int large, const int hg)
{
	const dem_mat_t *m = fe->mat;
	const uint32_t *restrict hex = fe->mesh->hex;
	const double *restrict xs = large ? fe->x : fe->mesh->X;
	const double *restrict vs = fe->v;
	double *restrict fi = fe->fi;
	double kaps = fe->o.hg_stiff, kapv = fe->o.hg_visc;
	dem_hex8_batch_t b;
	double xb[24 * NB], vb[24 * NB], fb[24 * NB], Q[12 * NB], P[NB], wp[NB];
	double eint = 0, epl = 0, ehg = 0, npl = 0, dt2 = INFINITY;
	size_t bad = 0;
	for (size_t bl = 0; bl < s->nb; bl++) {
		size_t el0 = s->e0 + bl * NB;
		int nv = s->e1 - el0 < NB ? (int)(s->e1 - el0) : NB;
		const uint32_t *h[NB];
		for (int e = 0; e < NB; e++)
			h[e] = hex + 8 * (el0 + (size_t)(e < nv ? e : nv - 1));
		size_t B = s->b0 + bl;
		const int run = fe->run[B];
		if (bl + PF < s->nb) {
			/* the element state of a block ahead */
			size_t Bp = B + PF;
			for (int k = 0; k < 6 * NB; k += 8) {
				__builtin_prefetch(fe->sig + Bp * 6 * NB + k, 1);
				if (large)
					__builtin_prefetch(fe->eps + Bp * 6 * NB + k, 1);
			}
			if (hg)
				for (int k = 0; k < 12 * NB; k += 8)
					__builtin_prefetch(fe->Qs + Bp * 12 * NB + k, 1);
			__builtin_prefetch(fe->ep + Bp * NB, 1);
			if (large)
				__builtin_prefetch(fe->kdt + Bp * NB, 0);
		}
		if (run) {
			/* nodes n..n+3: 12 consecutive doubles, transposed */
			for (int I = 0; I < 8; I++) {
				size_t n0 = 3 * (size_t)h[0][I];
				vec4 X[3], V[3];
				for (int c = 0; c < 3; c++) {
					X[c] = *(const uvec4 *)(xs + n0 + 4 * c);
					V[c] = *(const uvec4 *)(vs + n0 + 4 * c);
				}
				aos_soa(X);
				aos_soa(V);
				for (int c = 0; c < 3; c++) {
					*(uvec4 *)(xb + (8 * c + I) * NB) = X[c];
					*(uvec4 *)(vb + (8 * c + I) * NB) = V[c];
				}
			}
		} else
		/* one vector store per batch row, so that the kernel's vector
		 * loads are forwarded from the stores (scalar stores would not) */
		for (int I = 0; I < 8; I++) {
			size_t n0 = 3 * (size_t)h[0][I], n1 = 3 * (size_t)h[1][I];
			size_t n2 = 3 * (size_t)h[2][I], n3 = 3 * (size_t)h[3][I];
			for (int c = 0; c < 3; c++) {
				vec4 xv = { xs[n0 + c], xs[n1 + c], xs[n2 + c], xs[n3 + c] };
				vec4 vv = { vs[n0 + c], vs[n1 + c], vs[n2 + c], vs[n3 + c] };
				*(uvec4 *)(xb + (8 * c + I) * NB) = xv;
				*(uvec4 *)(vb + (8 * c + I) * NB) = vv;
			}
		}
		unsigned badm = dem_hex8_batch_kin(&b, xb, vb);
		if (badm) {
			/* leave the block as it was; report its first bad element */
			for (int e = 0; e < nv; e++)
				if (badm >> e & 1) {
					if (!bad)
						bad = el0 + (size_t)e + 1;
					break;
				}
			continue;
		}
		double *sg = fe->sig + B * 6 * NB, *ep = fe->ep + B * NB;
		vec4 s0[6];
		for (int k = 0; k < 6; k++)
			s0[k] = *(const uvec4 *)(sg + k * NB);
		double *kn = fe->kin ? fe->kin + B * (size_t)fe->nh * NB : NULL;
		unsigned pm = dem_mat_update_batch(m, dt, b.d[0], large ? b.w[0] : NULL, sg, ep, kn, wp,
						   fe->syc ? fe->syc + B * NB : NULL);
		/* energies of the lanes (vector across the batch) */
		vec4 vol, dE = { 0 }, q[12];
		vol = *(const uvec4 *)(b.vol);
		for (int i = 0; i < 12; i++)
			q[i] = *(const uvec4 *)b.q[i];
		for (int k = 0; k < 6; k++) {
			vec4 sn, dk;
			sn = *(const uvec4 *)(sg + k * NB);
			dk = *(const uvec4 *)(b.d[k]);
			dE += (s0[k] + sn) * dk;
		}
		dE *= 0.5 * dt * vol;
		vec4 dP;
		dP = *(const uvec4 *)(wp);
		dP *= vol;
		vec4 dH = { 0 };
		if (hg) {
			double *qs = fe->Qs + B * 12 * NB;
			vec4 qo = { 0 }, qn = { 0 }, Pv, t;
			for (int i = 0; i < 12; i++) {
				t = *(const uvec4 *)(qs + i * NB);
				qo += t * q[i];
			}
			/* in elements that flow this step, the stiffness form
			 * grows with the material's tangent, not its elastic
			 * modulus (see dem_fe_opts_t.hg_tangent) */
			double ksc[NB], *kp = NULL;
			if (pm && fe->o.hg_tangent) {
				const double *epl = fe->ep + B * NB;
				for (int e = 0; e < NB; e++)
					ksc[e] = pm >> e & 1 ? dem_mat_tangent_ratio(m, epl[e]) : 1;
				kp = ksc;
			}
			dem_hex8_batch_hg(&b, m, kaps, kapv, dt, kp, qs, Q, P);
			for (int i = 0; i < 12; i++) {
				t = *(const uvec4 *)(qs + i * NB);
				qn += t * q[i];
			}
			Pv = *(const uvec4 *)(P);
			/* work of the mean of the old and new stiffness forces
			 * (trapezoidal, like the stress work) and the viscous ones */
			dH = dt * (Pv - 0.5 * (qn - qo));
		}
		dem_hex8_batch_force(&b, sg, hg ? Q : NULL, fb);
		if (run) {
			/* the pairs of nodes I, J = I + 1 along the row: nodes
			 * n..n+4, each added to once (no store is read back) */
			static const int lo[4] = { 0, 3, 4, 7 }, hi[4] = { 1, 2, 5, 6 };
			const vec4 zero = { 0 };
			for (int p = 0; p < 4; p++) {
				size_t n0 = 3 * (size_t)h[0][lo[p]];
				vec4 Fv[3];
				double last[3];
				for (int c = 0; c < 3; c++) {
					/* element by element: the kernel stores f in
					 * halves, a whole-vector load would not be
					 * forwarded from them */
					const double *p0 = fb + (8 * c + lo[p]) * NB, *p1 = fb + (8 * c + hi[p]) * NB;
					vec4 f0 = { p0[0], p0[1], p0[2], p0[3] };
					vec4 f1 = { p1[0], p1[1], p1[2], p1[3] };
					Fv[c] = f0 + SHUF4(f1, zero, 4, 0, 1, 2);
					last[c] = f1[3];
				}
				soa_aos(Fv);
				for (int c = 0; c < 3; c++)
					*(uvec4 *)(fi + n0 + 4 * c) += Fv[c];
				for (int c = 0; c < 3; c++)
					fi[n0 + 12 + c] += last[c];
			}
		} else
			for (int e = 0; e < nv; e++)
				for (int I = 0; I < 8; I++) {
					size_t n = 3 * (size_t)h[e][I];
					fi[n] += fb[I * NB + e];
					fi[n + 1] += fb[(8 + I) * NB + e];
					fi[n + 2] += fb[(16 + I) * NB + e];
				}
		for (int e = 0; e < nv; e++) {
			eint += dE[e];
			epl += dP[e];
			ehg += dH[e];
			npl += pm >> e & 1;
		}
		if (large) {
			/* total strain: rotate, then add d dt; the step estimate */
			double *es = fe->eps + B * 6 * NB, *kd = fe->kdt + B * NB;
			vec4 E[6], d, a, bb, c;
			for (int k = 0; k < 6; k++)
				E[k] = *(const uvec4 *)(es + k * NB);
			a = *(const uvec4 *)(b.w[0]);
			bb = *(const uvec4 *)(b.w[1]);
			c = *(const uvec4 *)(b.w[2]);
			a *= dt;
			bb *= dt;
			c *= dt;
			vec4 F[6];
			F[0] = E[0] + a * E[3] - c * E[5];
			F[1] = E[1] + bb * E[4] - a * E[3];
			F[2] = E[2] + c * E[5] - bb * E[4];
			F[3] = E[3] + 2 * a * (E[1] - E[0]) - c * E[4] + bb * E[5];
			F[4] = E[4] + 2 * bb * (E[2] - E[1]) - a * E[5] + c * E[3];
			F[5] = E[5] + 2 * c * (E[0] - E[2]) - bb * E[3] + a * E[4];
			for (int k = 0; k < 6; k++) {
				d = *(const uvec4 *)(b.d[k]);
				F[k] += dt * d;
			}
			for (int k = 0; k < 6; k++)
				*(uvec4 *)(es + k * NB) = F[k];
			vec4 cm = { 0 }, kv;
			for (int k = 1; k <= 3; k++) {
				vec4 c0, c1, c2;
				c0 = *(const uvec4 *)(b.c[k][0]);
				c1 = *(const uvec4 *)(b.c[k][1]);
				c2 = *(const uvec4 *)(b.c[k][2]);
				vec4 c2s = c0 * c0 + c1 * c1 + c2 * c2;
				lvec4 gt = c2s > cm;
				cm = (vec4)((gt & (lvec4)c2s) | (~gt & (lvec4)cm));
			}
			kv = *(const uvec4 *)(kd);
			vec4 d2 = kv * vol * vol / cm;
			for (int e = 0; e < NB; e++)
				dt2 = d2[e] < dt2 ? d2[e] : dt2;
		}
	}
	s->sum[E_INT] = eint;
	s->sum[E_PL] = epl;
	s->sum[E_HG] = ehg;
	s->sum[E_NPL] = npl;
	s->dt2 = dt2;
	s->bad = bad;
}

static inline __attribute__((always_inline)) void slab_full(dem_fe_t *fe, slab_t *s, double dt, const int large)
{
	const dem_mat_t *m = fe->mat;
	const uint32_t *restrict hex = fe->mesh->hex;
	const double *restrict xs = large ? fe->x : fe->mesh->X;
	const double *restrict vs = fe->v;
	double *restrict fi = fe->fi;
	dem_hex8_full_t g;
	double eint = 0, epl = 0, npl = 0, dt2 = INFINITY;
	size_t bad = 0;
	for (size_t el = s->e0; el < s->e1; el++) {
		const uint32_t *h = hex + 8 * el;
		double xe[24], ve[24], f[24];
		for (int I = 0; I < 8; I++)
			for (int c = 0; c < 3; c++) {
				xe[8 * c + I] = xs[3 * (size_t)h[I] + c];
				ve[8 * c + I] = vs[3 * (size_t)h[I] + c];
			}
		if (dem_hex8_full_geom(xe, &g)) {
			if (!bad)
				bad = el + 1;
			continue;
		}
		dem_hex8_full_rate(&g, ve, 1);
		/* two batches of four Gauss points */
		double D[2][6 * NB], W[2][3 * NB], wp[2][NB], s0[2 * 6 * NB];
		for (int p = 0; p < 8; p++) {
			double d[6], w[3];
			dem_hex8_strain_rate(g.L[p], d, w);
			for (int k = 0; k < 6; k++)
				D[p / NB][k * NB + p % NB] = d[k];
			for (int k = 0; k < 3; k++)
				W[p / NB][k * NB + p % NB] = w[k];
		}
		double *sg = fe->sig + el * 2 * 6 * NB, *ep = fe->ep + el * 2 * NB;
		memcpy(s0, sg, sizeof s0);
		unsigned pm = 0;
		for (int q = 0; q < 2; q++)
			pm |= dem_mat_update_batch(m, dt, D[q], large ? W[q] : NULL, sg + q * 6 * NB,
						   ep + q * NB,
						   fe->kin ? fe->kin + (el * 2 + (size_t)q) * (size_t)fe->nh * NB : NULL,
						   wp[q], fe->syc ? fe->syc + (el * 2 + (size_t)q) * NB : NULL) << (NB * q);
		double sp[48], dm[6] = { 0 }, wm[3] = { 0 };
		for (int p = 0; p < 8; p++) {
			int q = p / NB, l = p % NB;
			double w = 0;
			for (int k = 0; k < 6; k++) {
				double sn = sg[q * 6 * NB + k * NB + l];
				sp[6 * p + k] = sn;
				w += (s0[q * 6 * NB + k * NB + l] + sn) * D[q][k * NB + l];
				dm[k] += g.wdet[p] * D[q][k * NB + l];
			}
			for (int k = 0; k < 3; k++)
				wm[k] += g.wdet[p] * W[q][k * NB + l];
			eint += 0.5 * dt * g.wdet[p] * w;
			epl += g.wdet[p] * wp[q][l];
		}
		npl += __builtin_popcount(pm);
		dem_hex8_full_force(&g, sp, 1, f);
		for (int I = 0; I < 8; I++) {
			size_t n = 3 * (size_t)h[I];
			fi[n] += f[I];
			fi[n + 1] += f[8 + I];
			fi[n + 2] += f[16 + I];
		}
		if (large) {
			double rv = 1 / g.vol, *es = fe->eps + 6 * el;
			rotate_strain(es, dt * rv * wm[0], dt * rv * wm[1], dt * rv * wm[2]);
			for (int k = 0; k < 6; k++)
				es[k] += dt * rv * dm[k];
			double d2 = fe->kdt[el] * g.vol * g.vol / midsection2(g.c);
			dt2 = d2 < dt2 ? d2 : dt2;
		}
	}
	s->sum[E_INT] = eint;
	s->sum[E_PL] = epl;
	s->sum[E_HG] = 0;
	s->sum[E_NPL] = npl;
	s->dt2 = dt2;
	s->bad = bad;
}

/* the loop chosen once, before time stepping: effects are constants in
 * each instance */
SIMD_CLONES
static void slab_run(dem_fe_t *fe, slab_t *s, double dt)
{
	if (fe->o.rule == DEM_FE_FULL) {
		if (fe->o.large)
			slab_full(fe, s, dt, 1);
		else
			slab_full(fe, s, dt, 0);
	} else if (fe->o.large) {
		if (fe->hg)
			slab_1pt(fe, s, dt, 1, 1);
		else
			slab_1pt(fe, s, dt, 1, 0);
	} else {
		if (fe->hg)
			slab_1pt(fe, s, dt, 0, 1);
		else
			slab_1pt(fe, s, dt, 0, 0);
	}
}

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC pop_options
#endif

/* ---- The step -------------------------------------------------------------- */

/* After the element loop, with several ranks (explicit.h, "Ranks"): the
 * forces on the shared planes (the halo), then one gather of every rank's
 * record: its slabs' sums, its nodes' sums and, from the top rank,
 * the top surface's coordinates and velocities.  fx is cleared where the
 * loads wrote to other ranks' nodes. */
static void ranks_exchange(dem_fe_t *fe)
{
	size_t np = 3 * fe->plane, d = sizeof(double);
	int top = fe->nrank - 1;
	if (fe->ext) {
		/* only where the loads may have written ([xlo, xhi)): the
		 * shot hook's top plane, not the whole array each step */
		size_t a = fe->xlo, b = fe->nu0 < fe->xhi ? fe->nu0 : fe->xhi;
		if (a < b)
			memset(fe->fx + 3 * a, 0, 3 * (b - a) * d);
		a = fe->nu1 > fe->xlo ? fe->nu1 : fe->xlo, b = fe->xhi;
		if (a < b)
			memset(fe->fx + 3 * a, 0, 3 * (b - a) * d);
	}
	double *lo = fe->rank > 0 ? fe->fi + 3 * fe->nu0 : NULL;
	double *hi = fe->rank < top ? fe->fi + 3 * fe->nu1 - np : NULL;
	dem_par_halo_sum(fe->par, lo, hi, np, fe->pbuf);
	fe->comm = (double)((size_t)((lo != NULL) + (hi != NULL)) * np * d);

	/* this rank's record: slabs, chunks, the top surface */
	double *g = fe->grec + fe->goff[fe->rank];
	for (int s = fe->s0; s < fe->s1; s++, g += SREC) {
		const slab_t *sl = &fe->slab[s];
		memcpy(g, sl->sum, E_N * d);
		g[E_N] = sl->dt2;
		g[E_N + 1] = (double)sl->bad;
	}
	/* the node chunks' sums, added in chunk order */
	for (int k = 0; k < DEM_CD_N; k++)
		g[k] = 0;
	for (int ch = 0; ch < NCHUNK; ch++)
		for (int k = 0; k < DEM_CD_N; k++)
			g[k] += fe->chunk[ch][k];
	g += DEM_CD_N;
	size_t t0 = 3 * (fe->nn - fe->plane);
	if (fe->rank == top) {
		memcpy(g, fe->x + t0, np * d);
		memcpy(g + np, fe->v + t0, np * d);
	}
	dem_par_gather(fe->par, fe->grec, d, fe->goff);
	fe->comm += (double)((fe->goff[fe->rank + 1] - fe->goff[fe->rank]) * d);

	/* every rank's records, in rank order: the node sums added so (into
	 * the first chunk, for energy_at_tn) */
	memset(fe->chunk, 0, sizeof fe->chunk);
	for (int r = 0; r <= top; r++) {
		g = fe->grec + fe->goff[r];
		for (int s = (int)fe->soff[r]; s < (int)fe->soff[r + 1]; s++, g += SREC) {
			slab_t *sl = &fe->slab[s];
			memcpy(sl->sum, g, E_N * d);
			sl->dt2 = g[E_N];
			sl->bad = (size_t)g[E_N + 1];
		}
		for (int k = 0; k < DEM_CD_N; k++)
			fe->chunk[0][k] += g[k];
		g += DEM_CD_N;
		if (r == top && fe->rank != top) {
			memcpy(fe->x + t0, g, np * d);
			memcpy(fe->v + t0, g + np, np * d);
		}
	}
}

/* The energies at t_n from the node chunks' sums. */
static void energy_at_tn(dem_fe_t *fe, double tn)
{
	double sum[DEM_CD_N] = { 0 };
	for (int ch = 0; ch < NCHUNK; ch++)
		for (int k = 0; k < DEM_CD_N; k++)
			sum[k] += fe->chunk[ch][k];
	dem_cd_energy(&fe->w, fe->steps, tn, sum, &fe->en);
}

int dem_fe_step(dem_fe_t *fe, double dt, dem_error_t *e)
{
	if (fe->failed)
		return dem_error_set(e, fe->fail.code, "%s", fe->fail.msg);
	if (!(dt > 0) || !isfinite(dt))
		dt = fe->dt_stable;
	double tn = fe->t;

	/* 1. external forces at t_n on x_n */
	fe->ext = fe->npl > 0 || fe->hook;
	fe->xlo = fe->plo, fe->xhi = fe->phi;
	if (fe->hook) {
		fe->xlo = fe->hlo < fe->xlo ? fe->hlo : fe->xlo;
		fe->xhi = fe->hhi > fe->xhi ? fe->hhi : fe->xhi;
	}
	if (fe->hook) {
		int rc = fe->hook(fe->hctx, tn, dt, fe->x, fe->v, fe->fx, e);
		if (rc) {
			memset(fe->fx, 0, 3 * fe->nn * sizeof *fe->fx);
			return rc;
		}
	}
	for (int i = 0; i < fe->npl; i++)
		apply_pressure(fe, &fe->pl[i], tn);

	/* 2-3. velocities and coordinates (Eqs. 1.6-1.7; Eq. 1.9 to start) */
	dem_cd_coef_t c;
	dem_cd_coef(&c, fe->steps, dt, fe->dt_prev, fe->o.damping);
	int nthr = fe->nthr;
	double w0 = dem_wall();
	if (fe->ntie)
		tie_gather(fe);
#pragma omp parallel for schedule(static) num_threads(nthr) if (nthr > 1)
	for (int ch = 0; ch < NCHUNK; ch++)
		node_chunk(fe, &c, ch);
	if (fe->ntie)
		tie_scatter(fe);
	double w1 = dem_wall();

	/* energies at t_n (several ranks: once their sums are in, below) */
	if (fe->nrank == 1)
		energy_at_tn(fe, tn);

	/* 4. elements on x_{n+1}: the slabs colour by colour (several
	 * ranks: this rank's, [s0, s1)) */
	int s0 = fe->s0, s1 = fe->s1;
#pragma omp parallel num_threads(nthr) if (nthr > 1)
	for (int c = 0; c < 4; c++) {
		if (fe->coff[c] == fe->coff[c + 1])
			continue;
#pragma omp for schedule(dynamic, 1)
		for (int o = fe->coff[c]; o < fe->coff[c + 1]; o++)
			if (fe->order[o] >= s0 && fe->order[o] < s1)
				slab_run(fe, &fe->slab[fe->order[o]], dt);
	}
	double w2 = dem_wall();
	if (fe->nrank > 1) {
		ranks_exchange(fe);
		energy_at_tn(fe, tn);
	}
	double w3 = dem_wall();
	fe->node_s += w1 - w0;
	fe->elem_s += w2 - w1;
	fe->comm_s += w3 - w2;

	size_t bad = 0;
	double dt2 = INFINITY;
	for (int s = 0; s < fe->nslab; s++) {
		slab_t *sl = &fe->slab[s];
		fe->w.eint += sl->sum[E_INT];
		fe->w.epl += sl->sum[E_PL];
		fe->w.ehg += sl->sum[E_HG];
		fe->nplastic += sl->sum[E_NPL];
		dt2 = sl->dt2 < dt2 ? sl->dt2 : dt2;
		if (sl->bad && !bad)
			bad = sl->bad;
	}
	fe->t = tn + dt;
	fe->dt_prev = dt;
	fe->steps++;
	fe->cycles += (double)fe->ne;
	if (bad) {
		int i, j, k;
		size_t el = bad - 1;
		elem_ijk(fe->mesh, el, &i, &j, &k);
		fe->failed = 1;
		dem_error_set(&fe->fail, DEM_ENUMERIC, "element %zu (i, j, k = %d, %d, %d) inverted or "
			      "degenerate at t = %.9g s (step %ld)", el, i, j, k, fe->t, fe->steps);
		return dem_error_set(e, DEM_ENUMERIC, "%s", fe->fail.msg);
	}
	if (fe->o.large)
		fe->dt_stable = fe->o.dt_factor * sqrt(dt2);
	return DEM_OK;
}

/* ---- State ------------------------------------------------------------------ */

double dem_fe_dt(const dem_fe_t *fe)
{
	return fe->dt_stable;
}

double dem_fe_time(const dem_fe_t *fe)
{
	return fe->t;
}

long dem_fe_steps(const dem_fe_t *fe)
{
	return fe->steps;
}

const double *dem_fe_coords(const dem_fe_t *fe)
{
	return fe->x;
}

double *dem_fe_velocity(dem_fe_t *fe)
{
	return fe->v;
}

const double *dem_fe_mass(const dem_fe_t *fe)
{
	return fe->pmass;
}

void dem_fe_displacements(const dem_fe_t *fe, double *u)
{
	for (size_t i = 0; i < 3 * fe->nn; i++)
		u[i] = fe->x[i] - fe->mesh->X[i];
}

void dem_fe_fields(const dem_fe_t *fe, double *sig, double *eps, double *ep)
{
	const dem_mesh_t *m = fe->mesh;
	for (size_t el = 0; el < fe->ne; el++) {
		if (fe->o.rule == DEM_FE_1PT) {
			size_t b;
			int l;
			elem_lane(fe, el, &b, &l);
			for (int k = 0; k < 6; k++) {
				if (sig)
					sig[6 * el + k] = fe->sig[(b * 6 + k) * NB + l];
				if (eps && fe->o.large)
					eps[6 * el + k] = fe->eps[(b * 6 + k) * NB + l];
			}
			if (ep)
				ep[el] = fe->ep[b * NB + l];
		} else if (sig || ep) {
			/* volume averages over the Gauss points */
			double xe[24];
			dem_hex8_full_t g;
			const double *sg = fe->sig + el * 2 * 6 * NB, *eg = fe->ep + el * 2 * NB;
			if (fe->o.large) {
				const uint32_t *h = m->hex + 8 * el;
				for (int I = 0; I < 8; I++)
					for (int c = 0; c < 3; c++)
						xe[8 * c + I] = fe->x[3 * (size_t)h[I] + c];
			} else {
				dem_mesh_gather(m, el, NULL, xe);
			}
			double wsum = 0, s6[6] = { 0 }, e1 = 0;
			int ok = !dem_hex8_full_geom(xe, &g);
			for (int p = 0; p < 8; p++) {
				int q = p / NB, l = p % NB;
				double w = ok ? g.wdet[p] : 1;
				wsum += w;
				for (int k = 0; k < 6; k++)
					s6[k] += w * sg[q * 6 * NB + k * NB + l];
				e1 += w * eg[q * NB + l];
			}
			for (int k = 0; k < 6; k++)
				if (sig)
					sig[6 * el + k] = s6[k] / wsum;
			if (ep)
				ep[el] = e1 / wsum;
		}
		if (eps && fe->o.large && fe->o.rule == DEM_FE_FULL)
			memcpy(eps + 6 * el, fe->eps + 6 * el, 6 * sizeof *eps);
		if (eps && !fe->o.large) {
			/* B(X) u: the mean displacement gradient, which is also
			 * the volume average of the Gauss point strains */
			double xe[24], ue[24], w[3];
			dem_hex8_1pt_t g;
			const uint32_t *h = m->hex + 8 * el;
			dem_mesh_gather(m, el, NULL, xe);
			for (int I = 0; I < 8; I++)
				for (int c = 0; c < 3; c++)
					ue[8 * c + I] = fe->x[3 * (size_t)h[I] + c] - m->X[3 * (size_t)h[I] + c];
			dem_hex8_1pt_geom(xe, &g);
			dem_hex8_1pt_rate(&g, ue);
			dem_hex8_strain_rate(g.L, eps + 6 * el, w);
		}
	}
}

void dem_fe_energy(const dem_fe_t *fe, dem_fe_energy_t *en)
{
	*en = fe->en;
}

void dem_fe_stats(const dem_fe_t *fe, dem_fe_stats_t *s)
{
	s->steps = fe->steps;
	s->elem_cycles = fe->cycles;
	s->plastic_updates = fe->nplastic;
	s->elem_s = fe->elem_s;
	s->node_s = fe->node_s;
	s->comm_s = fe->comm_s;
}

double dem_fe_comm_bytes(const dem_fe_t *fe)
{
	return fe->nrank > 1 ? fe->comm : 0;
}

void dem_fe_sync(dem_fe_t *fe)
{
	if (fe->nrank < 2)
		return;
	size_t d = sizeof(double), nh = (size_t)fe->nh;
	int full = fe->o.rule == DEM_FE_FULL;
	dem_par_t *p = fe->par;
	dem_par_gather(p, fe->x, 3 * d, fe->noff);
	dem_par_gather(p, fe->v, 3 * d, fe->noff);
	dem_par_gather(p, fe->fi, 3 * d, fe->noff);
	/* element state: per one-point block, or per element */
	size_t u = full ? 2 * NB : NB;
	dem_par_gather(p, fe->sig, 6 * u * d, fe->boff);
	dem_par_gather(p, fe->ep, u * d, fe->boff);
	if (fe->kin)
		dem_par_gather(p, fe->kin, nh * u * d, fe->boff);
	if (fe->Qs)
		dem_par_gather(p, fe->Qs, 12 * NB * d, fe->boff);
	if (fe->eps)
		dem_par_gather(p, fe->eps, (full ? 6 : 6 * NB) * d, fe->boff);
	if (fe->kdt)
		dem_par_gather(p, fe->kdt, (full ? 1 : NB) * d, fe->boff);
	if (fe->syc)
		dem_par_gather(p, fe->syc, u * d, fe->boff);
}

/* ---- Checkpoint ------------------------------------------------------------- */

/* Everything dem_fe_step reads that it wrote before, as one table: a field
 * added to struct dem_fe that carries over from step to step needs its
 * line here (and CKPT_VERSION raised).  Not saved: fx (zero between
 * steps), the per-step scratch (chunk, slab sums), what dem_fe_create
 * derives from the mesh (mass, slabs), and the failure (a failed model is
 * not saved). */
#define CKPT_VERSION 2 /* 2: blocks by banded slabs (thin meshes) */
#define CKPT_MAXITEM 32

static int ckpt_items(const dem_fe_t *cfe, dem_ckpt_item_t *it)
{
	dem_fe_t *fe = (dem_fe_t *)cfe;  /* saved from, or loaded into */
	size_t nn = fe->nn, ne = fe->ne, nl = fe->nblk * NB, d = sizeof(double);
	int full = fe->o.rule == DEM_FE_FULL, n = 0;
#define ITEM(nm, ptr, sz) (it[n++] = (dem_ckpt_item_t){ nm, ptr, sz })
	ITEM("x", fe->x, 3 * nn * d);
	ITEM("v", fe->v, 3 * nn * d);
	ITEM("fi", fe->fi, 3 * nn * d);
	ITEM("sig", fe->sig, (full ? ne * 2 * 6 * NB : 6 * nl) * d);
	ITEM("ep", fe->ep, (full ? ne * 2 * NB : nl) * d);
	if (fe->kin)
		ITEM("kin", fe->kin, (full ? ne * 2 * NB : nl) * (size_t)fe->nh * d);
	if (fe->Qs)
		ITEM("Qs", fe->Qs, 12 * nl * d);
	if (fe->eps)
		ITEM("eps", fe->eps, (full ? 6 * ne : 6 * nl) * d);
	if (fe->kdt)
		ITEM("kdt", fe->kdt, (full ? ne : nl) * d);
	ITEM("t", &fe->t, d);
	ITEM("dt_prev", &fe->dt_prev, d);
	ITEM("dt_stable", &fe->dt_stable, d);
	ITEM("steps", &fe->steps, sizeof fe->steps);
	ITEM("T0", &fe->w.T0, d);
	ITEM("wx_acc", &fe->w.wx_acc, d);
	ITEM("wd_acc", &fe->w.wd_acc, d);
	ITEM("eint", &fe->w.eint, d);
	ITEM("epl", &fe->w.epl, d);
	ITEM("ehg", &fe->w.ehg, d);
	ITEM("en", &fe->en, sizeof fe->en);
	ITEM("cycles", &fe->cycles, d);
	ITEM("nplastic", &fe->nplastic, d);
	ITEM("elem_s", &fe->elem_s, d);
	ITEM("node_s", &fe->node_s, d);
#undef ITEM
	return n;
}

/* The header: what the model was made from.  Zeroed before filling, so
 * its padding is zero and it can be compared and checksummed whole. */
typedef struct ckpt_head {
	char magic[8];
	uint32_t version, nitem;
	uint64_t nn, ne;
	int32_t nx, ny, nz, rule, large, hg;
	double dt_factor, damping, hg_stiff, hg_visc;
	uint32_t mesh_crc, mat_crc;
} ckpt_head_t;

static const char ckpt_magic[8] = "DEMFE\0ck";

static void ckpt_head(const dem_fe_t *fe, ckpt_head_t *h)
{
	const dem_mesh_t *m = fe->mesh;
	const dem_mat_t *a = fe->mat;
	dem_ckpt_item_t it[CKPT_MAXITEM];
	memset(h, 0, sizeof *h);
	memcpy(h->magic, ckpt_magic, sizeof h->magic);
	h->version = CKPT_VERSION;
	h->nitem = (uint32_t)ckpt_items(fe, it);
	h->nn = fe->nn, h->ne = fe->ne;
	h->nx = m->nx, h->ny = m->ny, h->nz = m->nz;
	h->rule = (int32_t)fe->o.rule, h->large = fe->o.large, h->hg = fe->hg;
	h->dt_factor = fe->o.dt_factor, h->damping = fe->o.damping;
	h->hg_stiff = fe->o.hg_stiff, h->hg_visc = fe->o.hg_visc;
	uint32_t c = dem_ckpt_crc(0, m->X, 3 * m->nn * sizeof *m->X);
	c = dem_ckpt_crc(c, m->hex, 8 * m->ne * sizeof *m->hex);
	if (m->fix)
		c = dem_ckpt_crc(c, m->fix, m->nn);
	if (m->ntie)
		c = dem_ckpt_crc(c, m->tie, 2 * m->ntie * sizeof *m->tie);
	h->mesh_crc = c;
	h->mat_crc = dem_ckpt_mat_crc(a);
}

int dem_fe_save(const dem_fe_t *fe, FILE *f, dem_error_t *e)
{
	ckpt_head_t h;
	dem_ckpt_item_t it[CKPT_MAXITEM];
	int n = ckpt_items(fe, it);
	ckpt_head(fe, &h);
	return dem_ckpt_write(f, &h, sizeof h, it, n, e);
}

int dem_fe_load(dem_fe_t *fe, FILE *f, dem_error_t *e)
{
	ckpt_head_t h, w;
	dem_ckpt_item_t it[CKPT_MAXITEM];
	int n = ckpt_items(fe, it);
	ckpt_head(fe, &w);
	if (dem_ckpt_read_head(f, &h, sizeof h, e))
		return e->code;
	if (memcmp(h.magic, ckpt_magic, sizeof h.magic))
		return dem_error_set(e, DEM_EINPUT, "checkpoint: not a model checkpoint (bad magic)");
	if (h.version != w.version)
		return dem_error_set(e, DEM_EINPUT, "checkpoint: model version %u, expected %u",
				     (unsigned)h.version, (unsigned)w.version);
	if (h.nn != w.nn || h.ne != w.ne || h.nx != w.nx || h.ny != w.ny || h.nz != w.nz)
		return dem_error_set(e, DEM_EINPUT, "checkpoint: of a mesh of %d x %d x %d elements "
				     "(%llu nodes), this one is %d x %d x %d (%zu nodes)", (int)h.nx,
				     (int)h.ny, (int)h.nz, (unsigned long long)h.nn, w.nx, w.ny, w.nz, fe->nn);
	if (h.mesh_crc != w.mesh_crc)
		return dem_error_set(e, DEM_EINPUT, "checkpoint: of another mesh (same sizes, other "
				     "coordinates or constraints)");
	if (h.rule != w.rule || h.large != w.large || h.hg != w.hg || h.nitem != w.nitem ||
	    memcmp(&h.dt_factor, &w.dt_factor, 4 * sizeof(double)))
		return dem_error_set(e, DEM_EINPUT, "checkpoint: of other run options (integration "
				     "rule, strain, time step factor, damping or hourglass control)");
	if (h.mat_crc != w.mat_crc)
		return dem_error_set(e, DEM_EINPUT, "checkpoint: of another material");
	if (dem_ckpt_read_items(f, &h, sizeof h, it, n, e))
		return e->code;
	fe->failed = 0;
	syc_reset(fe);
	return DEM_OK;
}
