/* cdiff.h - the parts of the central difference step that the explicit
 * engines (explicit.c, explicit2d.c) share, private to libdem: the
 * coefficients of a step, the energy record at t_n, and the time
 * histories of the pressure loads.  Static inline: cold code, once per
 * step or per load; the node loops that use the coefficients stay each
 * engine's own (explicit.h describes the step and the energies).
 */
#ifndef DEM_FE_CDIFF_H
#define DEM_FE_CDIFF_H

#include <math.h>
#include <stddef.h>

#include "core/error.h"
#include "fe/explicit.h"

/* The node loops' sums at t_n: kinetic energy, external work over the
 * two half steps (A: dt_n, before t_n; B: dt_{n+1}, after), damping work
 * likewise. */
enum { DEM_CD_T, DEM_CD_WXA, DEM_CD_WXB, DEM_CD_WDA, DEM_CD_WDB, DEM_CD_N };

typedef struct dem_cd_coef {
	double dt, dtp;      /* dt_{n+1}, dt_n */
	double co, cf, rden; /* v+ = (co v- + cf F / m) rden */
	double w1, w0;       /* v_n = w1 v+ + w0 v- (Eq. 1.3) */
	double k0, k1;       /* kinetic energy 1/2 m (k0 v- + k1 v+) v+ */
	double rdth;         /* 1 / dt_{n+1/2} */
	double alpha;
} dem_cd_coef_t;

/* The coefficients of the step of length dt after dtp (step number
 * steps, 0 for the first) with C = alpha M: Eq. 1.6 for the variable step
 * of Eq. 1.5, Eq. 1.9 to start. */
static inline void dem_cd_coef(dem_cd_coef_t *c, long steps, double dt, double dtp, double alpha)
{
	double a = alpha;
	c->dt = dt;
	c->dtp = dtp;
	c->alpha = a;
	if (steps == 0) {
		c->co = 2 - a * dt;
		c->cf = dt;
		c->rden = 0.5;
		c->w1 = 0;
		c->w0 = 1;
		c->k0 = 2;    /* v_{-1/2} = 2 v_0 - v_{1/2} */
		c->k1 = -1;
		c->rdth = 2 / dt;
	} else {
		double dth = 0.5 * (dtp + dt);
		c->co = 2 - a * dtp;
		c->cf = 2 * dth;
		c->rden = 1 / (2 + a * dt);
		c->w1 = dt / (2 * dth);
		c->w0 = dtp / (2 * dth);
		c->k0 = 1;
		c->k1 = 0;
		c->rdth = 1 / dth;
	}
}

/* The work sums an engine carries from step to step. */
typedef struct dem_cd_work {
	double T0;             /* kinetic energy at the start */
	double wx_acc, wd_acc; /* external and damping work up to t_n's half step */
	double eint, epl, ehg; /* internal, plastic, hourglass work up to t_n */
} dem_cd_work_t;

/* The energies at t_n from the node loop's sums (explicit.h), and the
 * external and damping work carried on to the next step. */
static inline void dem_cd_energy(dem_cd_work_t *w, long steps, double tn, const double sum[DEM_CD_N],
				 dem_fe_energy_t *en)
{
	if (steps == 0)
		w->T0 = sum[DEM_CD_T];
	en->t = tn;
	en->kinetic = sum[DEM_CD_T];
	en->external = w->wx_acc + sum[DEM_CD_WXA];
	en->damping = w->wd_acc + sum[DEM_CD_WDA];
	en->internal = w->eint;
	en->plastic = w->epl;
	en->hourglass = w->ehg;
	en->balance = en->kinetic + en->internal + en->hourglass + en->damping - en->external - w->T0;
	en->scale = fmax(fmax(fmax(fabs(en->kinetic), fabs(w->T0)), fmax(fabs(en->internal), fabs(en->hourglass))),
			 fmax(fabs(en->damping), fabs(en->external)));
	w->wx_acc = en->external + sum[DEM_CD_WXB];
	w->wd_acc = en->damping + sum[DEM_CD_WDB];
}

/* A pressure's time table (dem_fe_add_pressure): finite, times not
 * decreasing, at least one point. */
static inline int dem_cd_table_check(size_t nt, const double *t, const double *p, dem_error_t *e)
{
	if (nt < 1)
		return dem_error_set(e, DEM_EINPUT, "pressure: empty time history");
	for (size_t i = 0; i < nt; i++) {
		if (!isfinite(t[i]) || !isfinite(p[i]))
			return dem_error_set(e, DEM_EINPUT, "pressure: time history point %zu is not finite", i);
		if (i > 0 && t[i] < t[i - 1])
			return dem_error_set(e, DEM_EINPUT, "pressure: times must not decrease "
					     "(point %zu: %g after %g)", i, t[i], t[i - 1]);
	}
	return DEM_OK;
}

/* p(time) of the table: piecewise linear, constant beyond the ends; at a
 * repeated time (a jump) the right value. */
static inline double dem_cd_history(size_t n, const double *t, const double *p, double time)
{
	if (time < t[0])
		return p[0];
	if (time >= t[n - 1])
		return p[n - 1];
	/* the last point with t_i <= time */
	size_t lo = 0, hi = n - 1;
	while (hi - lo > 1) {
		size_t mid = (lo + hi) / 2;
		if (t[mid] <= time)
			lo = mid;
		else
			hi = mid;
	}
	double w = (time - t[lo]) / (t[hi] - t[lo]);
	return p[lo] + w * (p[hi] - p[lo]);
}

#endif
