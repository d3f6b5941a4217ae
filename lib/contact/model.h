/* model.h - a contact model assembled once from the effects a scene asks
 * for (DESIGN.md, "Effects"): the normal law (Eq. 3.45), an energy loss
 * (none, viscous damping Eqs. 3.70-3.76, or the hysteretic model
 * Eqs. 3.63-3.67) and, if asked for, Coulomb friction with co-rotation of
 * the previous tangential force (Eqs. 3.54-3.62).
 *
 * dem_contact_model_init picks one kernel for the combination (law exponent
 * 1, 1.5, 2 or general x energy loss x friction): the hot loop calls it
 * through cm->kernel and branches on no effect.  An absent effect costs
 * nothing, and friction with mu = 0 gives the same forces as no friction.
 *
 * Conventions.  A contact has a contactor (a sphere) and a target (a facet
 * or the other sphere).  n is the unit normal pointing from the target to
 * the contactor; the force returned acts on the contactor, the target gets
 * its opposite.  vrel is the velocity of the contactor's material point at
 * the contact point minus the target's there.  The kernel sees the full
 * contact overlap delta (the overlap with the facet's plane, Fig. 3.7) and
 * the partial contact factor gamma (Eqs. 3.9, 3.15-3.16): the whole force,
 * damping and tangential stiffness included, is scaled by gamma, so the
 * facets of a flat surface sum to the full contact.
 *
 * State kept per contact pair, between steps (dem_contact_state_t): the
 * tangential force and the normal of the previous step, the largest
 * overlap.  Zero it (or call dem_contact_state_reset) when a pair comes
 * into contact; the pair functions of facet.h and sphere.h reset it when
 * the pair separates.
 */
#ifndef DEM_CONTACT_MODEL_H
#define DEM_CONTACT_MODEL_H

#include "contact/law.h"
#include "core/error.h"

enum { DEM_DAMP_NONE = 0, DEM_DAMP_VISCOUS = 1, DEM_DAMP_HYSTERESIS = 2 };
enum { DEM_PARTIAL_AREA = 0, DEM_PARTIAL_VOLUME = 1 };  /* Eq. 3.15 / 3.16 */

/* What a scene asks for.  Zero-initialise, then fill. */
typedef struct dem_contact_param {
	dem_law_t law;    /* from dem_law_init or dem_law_hertz */
	int damping;      /* DEM_DAMP_* */
	double xi;        /* viscous: damping ratio in [0, 1) (Eq. 3.76) */
	double unload;    /* hysteresis: k'_n / k_n >= 1 (Eq. 3.63; dem_hyst_unload_ratio) */
	int friction;     /* 0 absent, 1 present */
	double mu;        /* Coulomb coefficient >= 0 (Eq. 3.48) */
	double kt_ratio;  /* k_t = kt_ratio gamma K_n (Eq. 3.72); 0: the default 2/7 */
	int partial;      /* DEM_PARTIAL_AREA or DEM_PARTIAL_VOLUME */
} dem_contact_param_t;

/* Default k_t / K_n.  A sphere's tangential motion at its contact point has
 * the effective mass 2/7 M (solid sphere, I = 2/5 M R^2), so k_t = 2/7 K_n
 * gives the tangential spring the frequency of the normal one, and the
 * normal time step (Box 3.1) stays the limit. */
#define DEM_CONTACT_KT_RATIO 0.2857142857142857

/* Per pair, kept between steps. */
typedef struct dem_contact_state {
	double Ft[3];  /* tangential force on the contactor at the previous step (Eq. 3.60) */
	double n[3];   /* normal at the previous step (zero: none yet) */
	double dmax;   /* largest overlap so far (Eq. 3.64) */
} dem_contact_state_t;

/* Kinematics of one contact at one step, as the geometry gives it. */
typedef struct dem_contact_kin {
	double delta;    /* full contact overlap > 0 */
	double gamma;    /* partial contact factor in (0, 1], 1 for full contact */
	double n[3];     /* unit normal, target -> contactor */
	double vrel[3];  /* contactor minus target velocity at the contact point */
	double r[3];     /* contact point minus contactor's centre (torque arm) */
	double wn;       /* (w_contactor - w_target) . n, for the co-rotation (Eq. 3.59) */
	double kn;       /* k_n of the pair (dem_law_kn) */
	double meff;     /* equivalent mass (Eq. 3.75), for the viscous damping */
	double dt;       /* time step, for the friction increments (Eqs. 3.58-3.59) */
} dem_contact_kin_t;

/* What the kernel returns. */
typedef struct dem_contact_out {
	double F[3];  /* total force on the contactor (normal + tangential) */
	double T[3];  /* torque on the contactor about its centre */
	double Fn;    /* magnitude of the normal force (gamma and damping included) */
	double Ft;    /* magnitude of the tangential force */
} dem_contact_out_t;

typedef struct dem_contact_model dem_contact_model_t;
typedef void (*dem_contact_kernel_fn)(const dem_contact_model_t *cm, const dem_contact_kin_t *k,
                                      dem_contact_state_t *s, dem_contact_out_t *o);

struct dem_contact_model {
	dem_contact_param_t p;
	double m;          /* law exponent */
	double shift;      /* hysteresis: delta_0 = dmax shift, shift = 1 - (k_n/k'_n)^(1/m) (Eq. 3.64) */
	double kt_ratio;   /* resolved k_t / K_n */
	double dt_factor;  /* stiffness factor for the time step: (k'_n/k_n)^(1/m) with hysteresis, else 1 */
	dem_contact_kernel_fn kernel;
	char effects[160]; /* e.g. "law m=1.5, hysteresis k'/k=2.3, friction mu=0.2, partial area" */
};

/* Check the parameters and choose the kernel.  DEM_EINPUT with a message on
 * an out-of-range value. */
int dem_contact_model_init(dem_contact_model_t *cm, const dem_contact_param_t *p, dem_error_t *e);

/* Zero a pair's state. */
void dem_contact_state_reset(dem_contact_state_t *s);

/* The contact time step of Box 3.1 for one pair: overlap delta (<= 0 before
 * contact), normal approach speed vn, mass M (the sphere's for a rigid
 * target, the equivalent mass of Eq. 3.75 otherwise).  u_max from the
 * current energy (dem_dt_umax_state), the secant stiffness of Eq. 3.80
 * (times (k'_n/k_n)^(1/m) with hysteresis, whose unloading branch is that
 * much stiffer), then lambda 2 sqrt(M/K_L).  HUGE_VAL when there is nothing
 * to limit the step (no speed, no overlap, m > 1). */
double dem_contact_dt(const dem_contact_model_t *cm, double kn, double M, double delta,
                      double vn, double lambda);

/* One step of the friction model alone (Eqs. 3.57-3.62), for tests and for
 * drivers with their own normal force: co-rotate s->Ft from s->n to n and
 * about n by wn dt, add -kt (tangential part of vrel) dt, return to the
 * Coulomb cone mu Fn; stores the result and n in s and returns it in Ft. */
void dem_friction_step(dem_contact_state_t *s, const double n[3], const double vrel[3],
                       double wn, double dt, double kt, double mu, double Fn, double Ft[3]);

#endif
