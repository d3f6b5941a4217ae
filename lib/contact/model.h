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
 * facets of a flat surface sum to the full contact.  (With the potential
 * scheme, facet.h replaces the elastic part o->Fe n of a partial contact
 * by the gradient of its energy, from the branch bc, bg0 the kernel
 * reports.)
 *
 * State kept per contact pair, between steps (dem_contact_state_t): the
 * tangential force and the normal of the previous step, the largest
 * overlap, the separation correction's work.  Zero it (or call
 * dem_contact_state_reset) when a pair comes into contact; the pair
 * functions of facet.h and sphere.h reset it when the pair separates.
 *
 * Separation correction (beyond the thesis).  Box 3.1 with the step of
 * Eq. 3.83 does not conserve energy: the rigid sphere leaves a rigid wall up
 * to 4.3 % faster than it came with the linear law at lambda = 0.3, 0.8 %
 * with the Hertz law (Fig. 3.15b; examples/timestep).  The energy is made
 * in the step in which the pair separates (central differences conserve
 * v_{n+1/2}^2 + omega^2 u_n u_{n+1} in contact for the linear law), so no
 * lambda in the recommended range removes it.  The correction below makes
 * the elastic part of the normal force do, over a whole contact, exactly
 * the work its law prescribes:
 *
 *   - Central differences change a velocity by F h_n / M with the
 *     velocity step h_n = (dt_{n-1} + dt_n) / 2 (Box 3.1), so a body's
 *     kinetic energy changes exactly by M/2 (v_{n+1/2}^2 - v_{n-1/2}^2) =
 *     F h_n . (v_{n-1/2} + v_{n+1/2}) / 2, and that of the two bodies of a
 *     pair force F_n n_n (on the contactor; minus on the target) by
 *         F_n h_n n_n . (w_{n-1/2} + w_{n+1/2}) / 2
 *     (w: relative velocity, contactor minus target).  This is linear in
 *     F: the elastic part F_e (k_n delta^m, or the branch of Eq. 3.63 with
 *     hysteresis; gamma included) does the discrete work W_h = sum over the
 *     contact of that expression with F_e.  With several contacts on a
 *     body, or damping, the shares add up to the whole change.
 *   - The exact work of F_e from delta = 0 to delta = 0 is - integral F_e
 *     d delta: U(0) - U(0) = 0 for the power law; for the hysteretic model
 *     (Eqs. 3.63-3.64) minus the area of the loop closed at the largest
 *     overlap reached, D = k_n dmax^(m+1)/(m+1) (1 - (k_n/k'_n)^(1/m)), which
 *     is what gives Eq. 3.67.
 *   - At separation, E = W_h - W_exact is the energy the integration made
 *     (E > 0) or lost (E < 0).  It is taken from the pair's relative normal
 *     motion, meff w_n^2 / 2: w_n' = sqrt(max(0, w_n^2 - 2 E / meff)),
 *     applied as the impulse J = meff (w_n' - w_n) n on the contactor and -J
 *     on the target.  Momentum is kept, the tangential motion and the spins
 *     are untouched, and w_n never changes sign (if E exceeds the normal
 *     kinetic energy, w_n' = 0 and the rest of E stays).
 *
 * Why only at separation: during contact the error W_h + U(delta) is
 * bounded and oscillates (the potential is stored, not lost); it is
 * defined against a closed form only when the contact has closed.  A force
 * added during contact would not be the law's.  Why only the elastic part:
 * the viscous force (Eq. 3.70) is not the gradient of a state function,
 * its exact work depends on the path the integration approximates, so
 * there is nothing exact to compare it with; its discrete work is kept.
 * Why only pairs of rigid bodies: the closed form needs F_e to be a function
 * of delta alone, i.e. gamma = 1 throughout (sphere/sphere; a sphere inside
 * one rigid facet), and an impulse on a deformable body's facet nodes would
 * be a shock in its mesh.  So the option is on by default (sepfix
 * DEM_SEPFIX_ON = 0) and the driver applies it to its rigid pairs.
 *
 * Use in a driver, per pair and step (h = (dt_prev + dt) / 2, the velocity
 * step the driver applies to the force; w the relative velocity at the
 * contact, for spheres that of the centres: the normal force does no work
 * on the spins):
 *   in contact, after cm->kernel:  dem_sepfix_record(st, n, w, o.Fe, h)
 *     with the kernel's normal n and w = w_{n-1/2}, before the update;
 *   on the first step apart (delta <= 0), with the state as it was before
 *     the pair function reset it (keep a copy):
 *     dem_sepfix_release(cm, &copy, kn, meff, n, w, J) with the current
 *     normal and relative velocity; add J to the contactor's momentum and
 *     -J to the target's (or the forces J / h and -J / h this step).
 * dem_contact_wall_test below is such a driver (the rigid sphere and wall
 * of Box 3.1).
 */
#ifndef DEM_CONTACT_MODEL_H
#define DEM_CONTACT_MODEL_H

#include "contact/law.h"
#include "core/error.h"

enum { DEM_DAMP_NONE = 0, DEM_DAMP_VISCOUS = 1, DEM_DAMP_HYSTERESIS = 2 };
/* partial contact (facet.h): the energy's gradient (the default; beyond
 * the thesis), the area factor (Eq. 3.15), the volume factor (Eq. 3.16);
 * for disks on segments (disk.h) the overlap area factor (Eq. 3.10) and
 * the contact width factor (Eq. 3.11), the others counting as area */
enum { DEM_PARTIAL_POTENTIAL = 0, DEM_PARTIAL_AREA = 1, DEM_PARTIAL_VOLUME = 2, DEM_PARTIAL_WIDTH = 3 };
enum { DEM_SEPFIX_ON = 0, DEM_SEPFIX_OFF = 1 };          /* separation correction (above) */

/* What a scene asks for.  Zero-initialise, then fill. */
typedef struct dem_contact_param {
	dem_law_t law;    /* from dem_law_init or dem_law_hertz */
	int damping;      /* DEM_DAMP_* */
	double xi;        /* viscous: damping ratio in [0, 1) (Eq. 3.76) */
	double unload;    /* hysteresis: k'_n / k_n >= 1 (Eq. 3.63; dem_hyst_unload_ratio) */
	int friction;     /* 0 absent, 1 present */
	double mu;        /* Coulomb coefficient >= 0 (Eq. 3.48) */
	double kt_ratio;  /* k_t = kt_ratio gamma K_n (Eq. 3.72); 0: the default 2/7 */
	int partial;      /* DEM_PARTIAL_POTENTIAL (0), _AREA, _VOLUME or (2D) _WIDTH */
	int sepfix;       /* DEM_SEPFIX_ON (default) or DEM_SEPFIX_OFF, for rigid pairs (above) */
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
	double W;      /* separation correction: discrete work of the elastic normal
	                  force so far, the last step's second half not yet in (J) */
	double P[3];   /* the last step's elastic normal impulse F_e h n (N s) */
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
	double Fe;    /* its elastic part: gamma k_n delta^m, or the branch of Eq. 3.63 */
	double Ft;    /* magnitude of the tangential force */
	double bc;    /* the elastic branch, F = bc (delta - bg0)^m: k_n and 0 on loading, */
	double bg0;   /* k'_n and delta_0 on unloading (Eqs. 3.63-3.64) */
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
	double loop;       /* hysteresis: loop energy D = loop k_n dmax^(m+1), loop = (1 - (k_n/k'_n)^(1/m))/(m+1); else 0 */
	int sepfix;        /* 1: rigid pairs get the separation correction */
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

/* The secant stiffness K_L behind dem_contact_dt (same arguments): the
 * step is lambda 2 sqrt(M / K_L).  For drivers that sum the stiffness of
 * several contacts on one body. */
double dem_contact_secant(const dem_contact_model_t *cm, double kn, double M, double delta,
                          double vn);

/* One step of the friction model alone (Eqs. 3.57-3.62), for tests and for
 * drivers with their own normal force: co-rotate s->Ft from s->n to n and
 * about n by wn dt, add -kt (tangential part of vrel) dt, return to the
 * Coulomb cone mu Fn; stores the result and n in s and returns it in Ft. */
void dem_friction_step(dem_contact_state_t *s, const double n[3], const double vrel[3],
                       double wn, double dt, double kt, double mu, double Fn, double Ft[3]);

/* ---- Separation correction (beyond the thesis; see above) ------------ */

/* In contact, after the kernel: add the work of the previous step's
 * elastic impulse s->P, now that w (= w_{n-1/2}) is known, and that of this
 * step's, F_e h n, with the velocity before the update; keep the latter in
 * s->P for the next call.  n: unit normal (target -> contactor), w: relative
 * velocity, contactor minus target; Fe: dem_contact_out_t.Fe; h: the
 * velocity step (dt_{n-1} + dt_n)/2 that the driver applies to the force. */
void dem_sepfix_record(dem_contact_state_t *s, const double n[3], const double w[3], double Fe,
                       double h);

/* On the first step apart, before the state is reset: close the work with
 * the relative velocity w after the last contact step, compare it with the
 * exact work (0, or minus the hysteresis loop at s->dmax), and write in J
 * the impulse on the contactor (-J on the target) that takes the
 * difference from the relative normal kinetic energy meff (n . w)^2 / 2
 * without changing the sign of n . w.  kn: the pair's k_n; meff: the
 * equivalent mass (Eq. 3.75).  Returns the energy taken (J; < 0: given
 * back), 0 and J = 0 when the pair is not separating (n . w <= 0) or there
 * is nothing to correct.  Whether cm->sepfix is on is the caller's test. */
double dem_sepfix_release(const dem_contact_model_t *cm, const dem_contact_state_t *s, double kn,
                          double meff, const double n[3], const double w[3], double J[3]);

/* The energy error of the pair so far, E = W_h - W_exact, if it separated
 * now with relative velocity w (for diagnostics and tests). */
double dem_sepfix_error(const dem_contact_model_t *cm, const dem_contact_state_t *s, double kn,
                        const double w[3]);

/* ---- The rigid sphere/rigid wall test with a contact model -------------- */

/* How dem_contact_wall_test chooses the step. */
enum {
	DEM_WALL_STEP_IMPACT = 0,  /* as Box 3.1: u_max of the impact speed (Eq. 3.81) */
	DEM_WALL_STEP_STATE = 1    /* as the drivers: dem_contact_dt from the current state */
};

typedef struct dem_wall_run {
	double ratio;    /* v_exit / v0, with the separation correction when cm->sepfix */
	double ratio0;   /* v_exit / v0 of the thesis scheme (before the correction) */
	double dE;       /* energy the correction took (J; < 0: given back), 0 without it */
	double Fmax;     /* largest normal force at the steps (N) */
	double umax;     /* largest overlap at the steps */
	double tc;       /* contact time: from u = 0 to the crossing of u = 0 on the way out
	                    (u is linear within a step) */
	long steps;      /* steps in contact, the first (u = 0) included */
} dem_wall_run_t;

/* Box 3.1 through the library: a rigid sphere of mass M at u(0) = 0 (u the
 * overlap) with speed v0 into a rigid wall, cm->kernel for the force
 * (gamma = 1, meff = M), central differences with dt_n = lambda dt_cr(u_n)
 * (Eqs. 3.80-3.83; times (k'_n/k_n)^(1/m) with hysteresis), until the
 * sphere has left (u < 0 moving out).  With the power law, no damping and
 * DEM_WALL_STEP_IMPACT, ratio0 is dem_dt_wall_test's number.  DEM_EINPUT
 * for bad arguments; DEM_ENUMERIC when the sphere does not leave within
 * 10^8 steps or the numbers overflow. */
int dem_contact_wall_test(const dem_contact_model_t *cm, double kn, double M, double v0,
                          double lambda, int step, dem_wall_run_t *r, dem_error_t *e);

#endif
