/* implicit.c - the implicit static stage of peen forming (see implicit.h). */
#include "fe/implicit.h"

#include <dlfcn.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cholmod.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "core/cost.h"
#include "fe/hex8_large.h"

struct dem_form {
	const dem_mesh_t *mesh;
	const dem_mat_t *mat;
	size_t nn, ne;
	double thick;            /* plate thickness */
	double *u, *un;          /* displacements (3 per node): iterate, converged */
	dem_hex8_hist_t *hc;     /* converged histories */
	dem_hex8_hist_t *hs;     /* start of the increment: hc + dlambda sbar */
	dem_hex8_hist_t *ht;     /* iterate */
	double *sbar;            /* the step's initial stresses, 48 per element (NULL: none) */
	double *R;               /* residual, 3 per node */
	uint8_t *fix;            /* constraint bits per node, this step */
	/* linear system on the free dofs */
	long *eq;                /* equation of each dof, -1 if constrained */
	size_t neq;
	int pattern_ok;          /* A, L match the constraints in fix */
	cholmod_common cc;
	cholmod_sparse *A;       /* upper triangle, sorted, packed */
	cholmod_factor *L;
	cholmod_dense *b;
	int step;
	double fref;             /* largest step load so far (N) */
	int large;               /* the last step was large strain */
};

/* ---- Plate mesh ----------------------------------------------------------- */

int dem_plate_mesh(const dem_plate_t *p, dem_mesh_t *mesh, dem_error_t *e)
{
	if (!(p->L > 0 && p->W > 0 && p->h > 0 && isfinite(p->L * p->W * p->h)))
		return dem_error_set(e, DEM_EINPUT, "plate: size %g x %g x %g is not positive",
				     p->L, p->W, p->h);
	if (!(p->dxy > 0) || p->nz < 1 || !(p->grade >= 1) || !isfinite(p->grade))
		return dem_error_set(e, DEM_EINPUT, "plate: bad element size, layers or grading");
	long nx = lround(p->L / p->dxy), ny = lround(p->W / p->dxy);
	if (nx < 1)
		nx = 1;
	if (ny < 1)
		ny = 1;
	dem_axis_t ax[3] = {
		{ -p->L / 2, p->L / 2, -p->L / 2, p->L / 2, p->L / (double)nx, 1, 0 },
		{ -p->W / 2, p->W / 2, -p->W / 2, p->W / 2, p->W / (double)ny, 1, 0 },
		{ -p->h, 0, -p->h, 0, p->h / p->nz, 1, 0 },
	};
	int rc = dem_mesh_box(mesh, ax, e);
	if (rc)
		return rc;
	if (mesh->nx != nx || mesh->ny != ny || mesh->nz != p->nz) {
		dem_mesh_free(mesh);
		return dem_error_set(e, DEM_ENUMERIC, "plate: mesh has %d x %d x %d elements, "
				     "expected %ld x %ld x %d", mesh->nx, mesh->ny, mesh->nz,
				     nx, ny, p->nz);
	}
	/* layer k from the peened face has thickness t0 grade^k (from both
	 * faces when two-sided), scaled to the thickness */
	int nz = p->nz;
	double *t = malloc((size_t)nz * sizeof *t), sum = 0;
	if (!t) {
		dem_mesh_free(mesh);
		return dem_error_nomem(e, "plate layers");
	}
	for (int k = 0; k < nz; k++) {
		int d = p->two_sided && nz - 1 - k < k ? nz - 1 - k : k;
		t[k] = pow(p->grade, d);
		sum += t[k];
	}
	mesh->gz[nz] = 0;
	for (int k = 0; k < nz; k++)  /* t[0] is the top layer */
		mesh->gz[nz - 1 - k] = mesh->gz[nz - k] - p->h * t[k] / sum;
	mesh->gz[0] = -p->h;
	free(t);
	for (int k = 0; k <= nz; k++)
		for (int j = 0; j <= mesh->ny; j++)
			for (int i = 0; i <= mesh->nx; i++)
				mesh->X[3 * dem_mesh_node(mesh, i, j, k) + 2] = mesh->gz[k];
	return DEM_OK;
}

/* ---- Model ------------------------------------------------------------------ */

void dem_form_opts_default(dem_form_opts_t *o)
{
	memset(o, 0, sizeof *o);
	o->rule = DEM_HEX8_EAS;
	o->tol = 1e-8;
	o->maxit = 12;
	o->ninc = 1;
	o->maxcut = 10;
}

int dem_form_create(dem_form_t **fp, const dem_mesh_t *mesh, const dem_mat_t *m,
		    dem_error_t *e)
{
	*fp = NULL;
	if (dem_mat_nhist(m))
		return dem_error_set(e, DEM_EINPUT, "form: the static stage keeps no back-stresses: "
				     "read a kinematic law with dem_mat_kin_as_iso() first");
	dem_form_t *f = calloc(1, sizeof *f);
	if (!f)
		return dem_error_nomem(e, "form model");
	f->mesh = mesh;
	f->mat = m;
	f->nn = mesh->nn;
	f->ne = mesh->ne;
	f->thick = mesh->gz[mesh->nz] - mesh->gz[0];
	f->u = calloc(3 * f->nn, sizeof *f->u);
	f->un = calloc(3 * f->nn, sizeof *f->un);
	f->R = calloc(3 * f->nn, sizeof *f->R);
	f->eq = malloc(3 * f->nn * sizeof *f->eq);
	f->fix = calloc(f->nn, 1);
	f->hc = calloc(f->ne, sizeof *f->hc);
	f->hs = calloc(f->ne, sizeof *f->hs);
	f->ht = calloc(f->ne, sizeof *f->ht);
	if (!f->u || !f->un || !f->R || !f->eq || !f->fix || !f->hc || !f->hs || !f->ht) {
		dem_form_free(f);
		return dem_error_nomem(e, "form model");
	}
	cholmod_start(&f->cc);
	f->cc.print = 0;
	f->cc.supernodal = CHOLMOD_SUPERNODAL;
	f->cc.error_handler = NULL;
	*fp = f;
	return DEM_OK;
}

void dem_form_free(dem_form_t *f)
{
	if (!f)
		return;
	if (f->A || f->L || f->b) {
		cholmod_free_sparse(&f->A, &f->cc);
		cholmod_free_factor(&f->L, &f->cc);
		cholmod_free_dense(&f->b, &f->cc);
	}
	if (f->hc)  /* cholmod_start ran */
		cholmod_finish(&f->cc);
	free(f->u), free(f->un), free(f->R), free(f->eq), free(f->fix);
	free(f->hc), free(f->hs), free(f->ht), free(f->sbar);
	free(f);
}

const double *dem_form_disp(const dem_form_t *f) { return f->un; }
const dem_hex8_hist_t *dem_form_hist(const dem_form_t *f) { return f->hc; }

/* ---- Profiles (Ch. 8.5.1) ------------------------------------------------------ */

int dem_form_profile(dem_form_t *f, const dem_profile_t *p, const dem_form_region_t *r,
		     dem_form_init_t mode, double scale, dem_error_t *e)
{
	if (!p || p->n < 1)
		return dem_error_set(e, DEM_EINPUT, "profile: no depth points");
	if (!f->sbar) {
		f->sbar = calloc(48 * f->ne, sizeof *f->sbar);
		if (!f->sbar)
			return dem_error_nomem(e, "initial stresses");
	}
	double D[36];
	dem_mat_elastic_stiffness(f->mat, D);
	for (size_t el = 0; el < f->ne; el++) {
		double X[24], xg[24];
		dem_mesh_gather(f->mesh, el, NULL, X);
		dem_hex8_gauss_points(X, xg);
		for (int q = 0; q < 8; q++) {
			double x = xg[q], y = xg[8 + q], z = xg[16 + q];
			if (x < r->x0 || x > r->x1 || y < r->y0 || y > r->y1)
				continue;
			double depth = r->bottom ? z + f->thick : -z;
			double s[6], eps[6], ep;
			dem_profile_eval(p, depth, s, eps, &ep);
			if (mode == DEM_FORM_STRAIN)
				for (int a = 0; a < 6; a++) {
					s[a] = 0;
					for (int b = 0; b < 6; b++)
						s[a] -= D[6 * a + b] * eps[b];
				}
			/* the profile's depth axis points into the material: on
			 * the bottom face that is +z, mirrored from the sample's
			 * -z, which turns the sign of the yz and zx shears */
			if (r->bottom)
				s[4] = -s[4], s[5] = -s[5];
			for (int a = 0; a < 6; a++)
				f->sbar[48 * el + 6 * q + a] += scale * s[a];
			if (ep > f->hc[el].ep[q])
				f->hc[el].ep[q] = ep;
		}
	}
	return DEM_OK;
}

/* ---- Constraints and the sparse pattern --------------------------------------------------- */

void dem_form_constrain(dem_form_t *f, const dem_bc_t bc[6], int minimal)
{
	dem_mesh_t tmp = *f->mesh;  /* dem_mesh_set_bc writes fix: use ours */
	dem_bc_t none[6] = { 0 };
	tmp.fix = f->fix;
	dem_mesh_set_bc(&tmp, bc ? bc : none);
	if (minimal) {
		const dem_mesh_t *m = f->mesh;
		/* mid-plane nodes nearest the centre and the centres of the
		 * +x and +y edges */
		int ic = m->nx / 2, jc = m->ny / 2, kc = m->nz / 2;
		f->fix[dem_mesh_node(m, ic, jc, kc)] |= DEM_FIX_X | DEM_FIX_Y | DEM_FIX_Z;
		f->fix[dem_mesh_node(m, m->nx, jc, kc)] |= DEM_FIX_Y | DEM_FIX_Z;
		f->fix[dem_mesh_node(m, ic, m->ny, kc)] |= DEM_FIX_Z;
	}
	f->pattern_ok = 0;
}

void dem_form_plane_strain(dem_form_t *f)
{
	for (size_t n = 0; n < f->nn; n++)
		f->fix[n] |= DEM_FIX_Y;
	f->pattern_ok = 0;
}

/* Equation numbers, the CSC pattern of the upper triangle (rows sorted)
 * from the 27-node neighbourhoods of the structured mesh, and CHOLMOD's
 * analysis (fill-reducing ordering, supernodes). */
static int build_system(dem_form_t *f, dem_error_t *e)
{
	const dem_mesh_t *m = f->mesh;
	cholmod_free_sparse(&f->A, &f->cc);
	cholmod_free_factor(&f->L, &f->cc);
	cholmod_free_dense(&f->b, &f->cc);
	size_t neq = 0;
	for (size_t n = 0; n < f->nn; n++)
		for (int i = 0; i < 3; i++)
			f->eq[3 * n + i] = f->fix[n] & (1u << i) ? -1 : (long)neq++;
	f->neq = neq;
	if (neq == 0)
		return dem_error_set(e, DEM_EINPUT, "form: every dof is constrained");
	/* count, then fill */
	size_t nnz = 0;
	for (int pass = 0; pass < 2; pass++) {
		int *Ap = pass ? f->A->p : NULL, *Ai = pass ? f->A->i : NULL;
		size_t cnt = 0, col = 0;
		for (int k = 0; k <= m->nz; k++)
			for (int j = 0; j <= m->ny; j++)
				for (int i = 0; i <= m->nx; i++) {
					size_t nJ = dem_mesh_node(m, i, j, k);
					for (int c = 0; c < 3; c++) {
						long ec = f->eq[3 * nJ + c];
						if (ec < 0)
							continue;
						if (pass)
							Ap[col] = (int)cnt;
						col++;
						for (int dk = -1; dk <= 1; dk++)
							for (int dj = -1; dj <= 1; dj++)
								for (int di = -1; di <= 1; di++) {
									int ii = i + di, jj = j + dj, kk = k + dk;
									if (ii < 0 || jj < 0 || kk < 0 || ii > m->nx ||
									    jj > m->ny || kk > m->nz)
										continue;
									size_t nI = dem_mesh_node(m, ii, jj, kk);
									for (int r = 0; r < 3; r++) {
										long er = f->eq[3 * nI + r];
										if (er < 0 || er > ec)
											continue;
										if (pass)
											Ai[cnt] = (int)er;
										cnt++;
									}
								}
					}
				}
		if (pass) {
			Ap[col] = (int)cnt;
		} else {
			nnz = cnt;
			if (nnz > INT32_MAX)
				return dem_error_set(e, DEM_EIO, "form: matrix too large");
			f->A = cholmod_allocate_sparse(neq, neq, nnz, 1, 1, 1, CHOLMOD_REAL, &f->cc);
			f->b = cholmod_zeros(neq, 1, CHOLMOD_REAL, &f->cc);
			if (!f->A || !f->b)
				return dem_error_nomem(e, "sparse matrix");
		}
	}
	memset(f->A->x, 0, nnz * sizeof(double));
	/* Fill-reducing order: nested dissection (METIS).  The plate is a 2D
	 * grid of node columns, where nested dissection is the right order
	 * and CHOLMOD's default choice is not: on the strip with 2 mm
	 * elements in plane it gave a factor of 5.5e8 nonzeros (88 s),
	 * METIS 6.6e7 (3.6 s).  AMD when CHOLMOD has no METIS. */
	f->cc.nmethods = 1;
	f->cc.method[0].ordering = CHOLMOD_METIS;
	f->L = cholmod_analyze(f->A, &f->cc);
	if (!f->L && f->cc.status == CHOLMOD_NOT_INSTALLED) {
		f->cc.status = CHOLMOD_OK;
		f->cc.method[0].ordering = CHOLMOD_AMD;
		f->L = cholmod_analyze(f->A, &f->cc);
	}
	if (!f->L)
		return dem_error_set(e, DEM_EIO, "form: CHOLMOD analysis failed (status %d)",
				     f->cc.status);
	f->pattern_ok = 1;
	return DEM_OK;
}

/* Add the element matrix K (24 x 24, dof 8 i + I) of element nodes nd to A. */
static void scatter(dem_form_t *f, const uint32_t *nd, const double *K)
{
	const int *Ap = f->A->p, *Ai = f->A->i;
	double *Ax = f->A->x;
	for (int J = 0; J < 8; J++)
		for (int j = 0; j < 3; j++) {
			long c = f->eq[3 * (size_t)nd[J] + j];
			if (c < 0)
				continue;
			for (int I = 0; I < 8; I++) {
				const long *eI = f->eq + 3 * (size_t)nd[I];
				long first = eI[0] >= 0 ? eI[0] : eI[1] >= 0 ? eI[1] : eI[2];
				if (first < 0 || first > c)
					continue;
				/* lower bound of first in column c */
				int lo = Ap[c], hi = Ap[c + 1];
				while (lo < hi) {
					int mid = (lo + hi) / 2;
					if (Ai[mid] < first)
						lo = mid + 1;
					else
						hi = mid;
				}
				for (int i = 0; i < 3; i++) {
					long r = eI[i];
					if (r < 0)
						continue;
					if (r > c)
						break;
					Ax[lo++] += K[(8 * i + I) * 24 + 8 * j + J];
				}
			}
		}
}

/* Internal forces (and the tangent when K) at the iterate u from the
 * increment's start state hs.  tangent == 2 (large strain, first iteration
 * of an increment): the tangent of the converged state hc instead, whose
 * stresses are in equilibrium; the dlambda sbar just added is the load of
 * Eq. 8.9, and its initial-stress stiffness, unbalanced, can make the
 * tangent of a thin plate indefinite (a compressive membrane force above
 * the buckling load of the free plate) where the equilibrium path is not.  The residual R = -f_int; returns the norm
 * of R over the free dofs in *rn.  Nonzero: the element code (1 inverted,
 * 2 no local convergence) with its number in *bad. */
static int assemble(dem_form_t *f, const dem_form_opts_t *o, int tangent, double *rn,
		    size_t *bad)
{
	const dem_mesh_t *m = f->mesh;
	memset(f->R, 0, 3 * f->nn * sizeof *f->R);
	if (tangent)
		memset(f->A->x, 0, (size_t)((int *)f->A->p)[f->neq] * sizeof(double));
	const int eas = o->rule == DEM_HEX8_EAS;
	/* Eight colours by the parity of (i, j, k): two elements of a colour
	 * share no node, so a colour's elements add into R and A in parallel
	 * without a race, and the sums are the same bit for bit on any number
	 * of threads (each entry receives its elements in colour order). */
	for (int c = 0; c < 8; c++) {
		const int i0 = c & 1, j0 = c >> 1 & 1, k0 = c >> 2 & 1;
		const int ni = (m->nx - i0 + 1) / 2, nj = (m->ny - j0 + 1) / 2, nk = (m->nz - k0 + 1) / 2;
		const long nrow = (long)nj * nk;
		size_t first = SIZE_MAX;
		int frc = 0;
#pragma omp parallel for schedule(dynamic, 4) if (nrow * ni >= 256)
		for (long r = 0; r < nrow; r++) {
			const int j = j0 + 2 * (int)(r % nj), k = k0 + 2 * (int)(r / nj);
			for (int i = i0; i < m->nx; i += 2) {
				const size_t el = dem_mesh_elem(m, i, j, k);
				const uint32_t *nd = m->hex + 8 * el;
				double X[24], du[24], un[24], fint[24], K[576];
				dem_mesh_gather(m, el, NULL, X);
				for (int I = 0; I < 8; I++)
					for (int d = 0; d < 3; d++) {
						size_t q = 3 * (size_t)nd[I] + d;
						un[8 * d + I] = f->un[q];
						du[8 * d + I] = f->u[q] - f->un[q];
					}
				int rc = o->large
					? dem_hex8_large(f->mat, eas, X, un, du, &f->hs[el], &f->ht[el], fint,
							 tangent == 1 ? K : NULL, NULL)
					: dem_hex8_static(f->mat, o->rule, X, du, &f->hs[el], &f->ht[el], fint,
							  tangent ? K : NULL, NULL);
				if (!rc && tangent == 2) {
					static const double zero[24];
					dem_hex8_hist_t hk = f->hc[el];
					double fk[24];
					rc = dem_hex8_large(f->mat, eas, X, un, zero, &f->hc[el], &hk, fk, K, NULL);
				}
				if (rc) {
#pragma omp critical(form_bad)
					if (el < first) {
						first = el;
						frc = rc;
					}
					continue;
				}
				for (int I = 0; I < 8; I++)
					for (int d = 0; d < 3; d++)
						f->R[3 * (size_t)nd[I] + d] -= fint[8 * d + I];
				if (tangent)
					scatter(f, nd, K);
			}
		}
		if (frc) {   /* the lowest failing element of the first colour with one */
			*bad = first;
			return frc;
		}
	}
	double s = 0;
	for (size_t d = 0; d < 3 * f->nn; d++)
		if (f->eq[d] >= 0)
			s += f->R[d] * f->R[d];
	*rn = sqrt(s);
	return 0;
}

/* Start an increment: histories hc plus dlam sbar, iterate at un. */
static void start_increment(dem_form_t *f, double dlam)
{
	memcpy(f->u, f->un, 3 * f->nn * sizeof *f->u);
	for (size_t el = 0; el < f->ne; el++) {
		f->hs[el] = f->hc[el];
		if (f->sbar)
			for (int k = 0; k < 48; k++)
				f->hs[el].sig[k] += dlam * f->sbar[48 * el + k];
		memcpy(f->ht[el].alpha, f->hs[el].alpha, sizeof f->ht[el].alpha);
	}
}

int dem_form_threads(int n)
{
	/* OpenBLAS's own calls, looked up in the running program (Debian
	 * switches libblas.so.3 between BLAS builds); none in another BLAS */
	void *self = dlopen(NULL, RTLD_LAZY);
	void (*set)(int) = NULL;
	int (*get)(void) = NULL, (*par)(void) = NULL;
	if (self) {
		*(void **)&set = dlsym(self, "openblas_set_num_threads");
		*(void **)&get = dlsym(self, "openblas_get_num_threads");
		*(void **)&par = dlsym(self, "openblas_get_parallel");
	}
	if (n > 0) {
#ifdef _OPENMP
		omp_set_num_threads(n);
#endif
		if (set)
			set(n);
	}
	/* a sequential build (openblas_get_parallel() 0) keeps to one thread
	 * whatever it was told */
	int blas = get ? (par && par() == 0 ? 1 : get()) : 0;
	if (self)
		dlclose(self);
	return blas;
}

int dem_form_step(dem_form_t *f, const dem_form_opts_t *o, dem_form_stats_t *st,
		  dem_error_t *e)
{
	if (o->large && o->rule == DEM_HEX8_BBAR)
		return dem_error_set(e, DEM_EINPUT, "form: the B-bar rule is small strain only");
	if (o->ninc < 1 || o->maxit < 1 || !(o->tol > 0))
		return dem_error_set(e, DEM_EINPUT, "form: bad solution controls");
	f->step++;
	f->large = o->large;
	int rc;
	if (!f->pattern_ok && (rc = build_system(f, e)))
		return rc;
	size_t bad = 0;
	double t0 = dem_wall();

	/* |F|, the equivalent load of the whole step (Eq. 8.5): the residual
	 * with all of sbar added to the converged state */
	double fnorm;
	start_increment(f, 1);
	rc = assemble(f, o, 0, &fnorm, &bad);
	st->assemble_s += dem_wall() - t0;
	if (rc)
		return dem_error_set(e, DEM_ENUMERIC, "form: step %d: element %zu is %s at the start",
				     f->step, bad, rc == DEM_HEX8_INVERTED ? "inverted" : "not converging");
	st->fnorm = fnorm;
	if (fnorm > f->fref)
		f->fref = fnorm;
	st->neq = f->neq;
	st->lnz = f->cc.lnz;
	st->flops = f->cc.fl;

	double lam = 0, dlam = 1.0 / o->ninc;
	int cuts = 0;
	while (lam < 1 - 1e-12) {
		if (dlam > 1 - lam)
			dlam = 1 - lam;
		start_increment(f, dlam);
		int inc = st->increments + 1, ok = 0, it;
		double r0 = 0, ref = 0, rn = 0, dun = 0;
		for (it = 0; it <= o->maxit; it++) {
			double ta = dem_wall();
			rc = assemble(f, o, o->large && it == 0 ? 2 : 1, &rn, &bad);
			st->assemble_s += dem_wall() - ta;
			if (rc || !isfinite(rn))
				break;
			if (it == 0) {
				/* relative to the step's load, or the job's when the
				 * step has none (a change of constraints only) */
				r0 = rn;
				ref = fmax(fnorm, f->fref);
				if (ref == 0)
					ref = r0;
			}
			double rrel = ref > 0 ? rn / ref : 0;
			if (o->log)
				o->log(o->ctx, f->step, inc, lam + dlam, it, rn, rrel, dun);
			if (rn <= o->tol * ref || ref == 0) {
				ok = 1;
				st->rnorm = rn;
				st->rrel = rrel;
				break;
			}
			if (it == o->maxit || (it >= 2 && rn > 1e3 * r0))
				break;
			/* K du = R */
			double tf = dem_wall();
			if (!cholmod_factorize(f->A, f->L, &f->cc) ||
			    f->cc.status == CHOLMOD_NOT_POSDEF) {
				st->factor_s += dem_wall() - tf;
				break;
			}
			st->factorisations++;
			double ts = dem_wall();
			st->factor_s += ts - tf;
			double *bx = f->b->x;
			for (size_t d = 0; d < 3 * f->nn; d++)
				if (f->eq[d] >= 0)
					bx[f->eq[d]] = f->R[d];
			cholmod_dense *x = cholmod_solve(CHOLMOD_A, f->L, f->b, &f->cc);
			if (!x)
				return dem_error_nomem(e, "linear solve");
			const double *xx = x->x;
			dun = 0;
			for (size_t d = 0; d < 3 * f->nn; d++)
				if (f->eq[d] >= 0) {
					f->u[d] += xx[f->eq[d]];
					dun += xx[f->eq[d]] * xx[f->eq[d]];
				}
			dun = sqrt(dun);
			cholmod_free_dense(&x, &f->cc);
			st->solve_s += dem_wall() - ts;
			st->iterations++;
		}
		if (ok) {
			lam += dlam;
			memcpy(f->un, f->u, 3 * f->nn * sizeof *f->u);
			dem_hex8_hist_t *t = f->hc;
			f->hc = f->ht;
			f->ht = t;
			st->increments++;
			/* grow a cut increment again after one that converged
			 * with iterations to spare */
			cuts = 0;
			if (it < o->maxit && dlam < 1.0 / o->ninc)
				dlam = fmin(2 * dlam, 1.0 / o->ninc);
			continue;
		}
		/* cut back from the last converged state */
		if (++cuts > o->maxcut) {
			st->lambda = lam;
			memcpy(f->u, f->un, 3 * f->nn * sizeof *f->u);
			if (rc)
				return dem_error_set(e, DEM_ENUMERIC, "form: step %d: element %zu %s "
						     "at lambda %.6g after %d cut-backs", f->step, bad,
						     rc == DEM_HEX8_INVERTED ? "inverted" : "did not converge",
						     lam + dlam, cuts - 1);
			return dem_error_set(e, DEM_ENUMERIC, "form: step %d: Newton diverged at "
					     "lambda %.6g after %d cut-backs (residual %.3g N)",
					     f->step, lam + dlam, cuts - 1, rn);
		}
		st->cutbacks++;
		dlam *= 0.5;
	}
	/* the step's profiles are spent: sbar now lives in the stresses */
	if (f->sbar)
		memset(f->sbar, 0, 48 * f->ne * sizeof *f->sbar);
	st->lambda = 1;
	return DEM_OK;
}

/* ---- Results ---------------------------------------------------------------------- */

/* Least squares: solve the n x n normal equations (n <= 6) in place. */
static int solve_small(int n, double *A, double *b)
{
	for (int k = 0; k < n; k++) {
		int piv = k;
		for (int i = k + 1; i < n; i++)
			if (fabs(A[i * n + k]) > fabs(A[piv * n + k]))
				piv = i;
		if (!(fabs(A[piv * n + k]) > 0))
			return -1;
		for (int j = 0; j < n; j++) {
			double t = A[k * n + j];
			A[k * n + j] = A[piv * n + j];
			A[piv * n + j] = t;
		}
		double t = b[k];
		b[k] = b[piv];
		b[piv] = t;
		for (int i = k + 1; i < n; i++) {
			double l = A[i * n + k] / A[k * n + k];
			for (int j = k; j < n; j++)
				A[i * n + j] -= l * A[k * n + j];
			b[i] -= l * b[k];
		}
	}
	for (int k = n - 1; k >= 0; k--) {
		double s = b[k];
		for (int j = k + 1; j < n; j++)
			s -= A[k * n + j] * b[j];
		b[k] = s / A[k * n + k];
	}
	return 0;
}

/* The deflection at node (i, j) of the mid-surface (k < 0: the mean of
 * the top and bottom faces' w, free of the thickness change) or of the
 * face at grid line k. */
static double node_w(const dem_form_t *f, int i, int j, int k)
{
	const dem_mesh_t *m = f->mesh;
	if (k >= 0)
		return f->un[3 * dem_mesh_node(m, i, j, k) + 2];
	return 0.5 * (f->un[3 * dem_mesh_node(m, i, j, 0) + 2] +
		      f->un[3 * dem_mesh_node(m, i, j, m->nz) + 2]);
}

static double mid_w(const dem_form_t *f, int i, int j)
{
	return node_w(f, i, j, -1);
}

/* w at (x, y) by bilinear interpolation: of the mid-surface (k < 0) or of
 * the face at grid line k. */
static double surface_w(const dem_form_t *f, double x, double y, int k)
{
	const dem_mesh_t *m = f->mesh;
	int i = 0, j = 0;
	while (i < m->nx - 1 && x > m->gx[i + 1])
		i++;
	while (j < m->ny - 1 && y > m->gy[j + 1])
		j++;
	double s = (x - m->gx[i]) / (m->gx[i + 1] - m->gx[i]);
	double t = (y - m->gy[j]) / (m->gy[j + 1] - m->gy[j]);
	s = fmin(fmax(s, 0), 1);
	t = fmin(fmax(t, 0), 1);
	double w00 = node_w(f, i, j, k), w10 = node_w(f, i + 1, j, k);
	double w01 = node_w(f, i, j + 1, k), w11 = node_w(f, i + 1, j + 1, k);
	return (1 - s) * (1 - t) * w00 + s * (1 - t) * w10 + (1 - s) * t * w01 + s * t * w11;
}

int dem_form_shape(const dem_form_t *f, double chord, int axis, double fx, double fy,
		   dem_form_shape_t *s, dem_error_t *e)
{
	const dem_mesh_t *m = f->mesh;
	double L = m->gx[m->nx] - m->gx[0], W = m->gy[m->ny] - m->gy[0];
	double span = axis ? W : L;
	if (!(chord > 0 && chord <= span * (1 + 1e-12)))
		return dem_error_set(e, DEM_EINPUT, "form: chord %g is not in (0, %g]", chord, span);
	/* scaled coordinates keep the normal equations well conditioned */
	double A[36] = { 0 }, b[6] = { 0 }, wmin = HUGE_VAL, wmax = -HUGE_VAL;
	double sc = fmax(L, W) / 2;
	for (int j = 0; j <= m->ny; j++)
		for (int i = 0; i <= m->nx; i++) {
			size_t n = dem_mesh_node(m, i, j, 0);
			double w = mid_w(f, i, j);
			wmin = fmin(wmin, w);
			wmax = fmax(wmax, w);
			double x = m->gx[i], y = m->gy[j];
			if (fabs(x) > fx * L / 2 * (1 + 1e-12) || fabs(y) > fy * W / 2 * (1 + 1e-12))
				continue;
			if (f->large) {  /* in the deformed configuration */
				x += f->un[3 * n];
				y += f->un[3 * n + 1];
			}
			x /= sc;
			y /= sc;
			double phi[6] = { 1, x, y, x * x, y * y, x * y };
			for (int a = 0; a < 6; a++) {
				b[a] += phi[a] * w;
				for (int c = 0; c < 6; c++)
					A[6 * a + c] += phi[a] * phi[c];
			}
		}
	if (solve_small(6, A, b))
		return dem_error_set(e, DEM_EINPUT, "form: too few nodes to fit the curvature "
				     "(fit region %g x %g of the plate)", fx, fy);
	s->kx = -2 * b[3] / (sc * sc);
	s->ky = -2 * b[4] / (sc * sc);
	s->kxy = -b[5] / (sc * sc);
	s->wmax = wmax - wmin;
	double c2 = chord / 2;
	s->arc = axis ? surface_w(f, 0, 0, -1) - 0.5 * (surface_w(f, 0, -c2, -1) + surface_w(f, 0, c2, -1))
		      : surface_w(f, 0, 0, -1) - 0.5 * (surface_w(f, -c2, 0, -1) + surface_w(f, c2, 0, -1));
	return DEM_OK;
}

int dem_form_gauge(const dem_form_t *f, double lx, double ly, double *height, dem_error_t *e)
{
	const dem_mesh_t *m = f->mesh;
	double p = lx / 2, q = ly / 2;
	if (!(p > 0 && q > 0 && p <= m->gx[m->nx] * (1 + 1e-12) && -p >= m->gx[0] * (1 + 1e-12) &&
	      q <= m->gy[m->ny] * (1 + 1e-12) && -q >= m->gy[0] * (1 + 1e-12)))
		return dem_error_set(e, DEM_EINPUT, "form: the gauge's balls (a %g x %g rectangle) "
				     "are not on the plate (%g x %g)", lx, ly, m->gx[m->nx] - m->gx[0],
				     m->gy[m->ny] - m->gy[0]);
	/* The face the balls touch: the one opposite the peened top. */
	double w[4];
	for (int c = 0; c < 4; c++)
		w[c] = surface_w(f, c & 1 ? p : -p, c & 2 ? q : -q, 0);
	/* the plane of the four contacts (least squares: exact when they are
	 * coplanar): its height at the centre is their mean, its slopes the
	 * mean differences across the rectangle */
	double a = 0.25 * (w[0] + w[1] + w[2] + w[3]);
	double bx = 0.25 * (w[1] - w[0] + w[3] - w[2]) / p;
	double by = 0.25 * (w[2] - w[0] + w[3] - w[1]) / q;
	/* the indicator reads along the normal of the plane of the balls */
	*height = (surface_w(f, 0, 0, 0) - a) / sqrt(1 + bx * bx + by * by);
	return DEM_OK;
}

/* Elements around coordinate 0 of a grid: one or two indices. */
static int around_zero(const double *g, int n, int idx[2])
{
	double tol = 1e-9 * (g[n] - g[0]);
	for (int i = 1; i < n; i++)
		if (fabs(g[i]) <= tol) {
			idx[0] = i - 1;
			idx[1] = i;
			return 2;
		}
	int i = 0;
	while (i < n - 1 && g[i + 1] < 0)
		i++;
	idx[0] = i;
	return 1;
}

void dem_form_centre_profile(const dem_form_t *f, int *np, double *depth, double *sig,
			     double *ep)
{
	const dem_mesh_t *m = f->mesh;
	int ix[2], iy[2];
	int nxa = around_zero(m->gx, m->nx, ix), nya = around_zero(m->gy, m->ny, iy);
	int n = 0;
	for (int k = m->nz - 1; k >= 0; k--)
		for (int top = 1; top >= 0; top--) {  /* upper Gauss points first */
			double z = 0, s[6] = { 0 }, e = 0;
			int cnt = 0;
			for (int a = 0; a < nxa; a++)
				for (int c = 0; c < nya; c++) {
					size_t el = dem_mesh_elem(m, ix[a], iy[c], k);
					double X[24], xg[24];
					dem_mesh_gather(m, el, NULL, X);
					dem_hex8_gauss_points(X, xg);
					for (int q = 4 * top; q < 4 * top + 4; q++) {
						z += xg[16 + q];
						for (int t = 0; t < 6; t++)
							s[t] += f->hc[el].sig[6 * q + t];
						e += f->hc[el].ep[q];
						cnt++;
					}
				}
			depth[n] = -z / cnt;
			for (int t = 0; t < 6; t++)
				sig[6 * n + t] = s[t] / cnt;
			ep[n] = e / cnt;
			n++;
		}
	*np = n;
}
