/* disk.h - disk/segment and disk/disk contact in two dimensions (Han 2004,
 * Ch. 3.2.1), with the normal laws of law.h at dim = 2 and the kernels of
 * model.h (friction, damping) unchanged.
 *
 * A disk is a dem_sphere_t (facet.h) in the plane z = 0: x and v in the
 * plane (their z components zero), its spin w[2] about z, kn from a 2D
 * law (dem_law_kn with law.dim = 2: a force per unit thickness).  Masses
 * are per unit thickness too.  Disk/disk contact is then
 * dem_contact_sphere_sphere (sphere.h) as it stands: delta = R1 + R2 - d
 * (Eq. 3.8), n along the line of centres, and the co-rotation of the
 * tangential force (Eqs. 3.57-3.59) keeps a force in the plane there
 * (the normal turns about z, (w2 - w1) . n = 0).
 *
 * Disk/segment.  The segment A -> B has the disk on its left: its unit
 * normal nf = (-t_y, t_x), t = (B - A)/L, points out of the solid to the
 * disk.  With d = (O - A) . nf the distance of the disk's centre O from the
 * segment's line (0 < d < R for contact; a centre behind the line is no
 * contact), the full contact (the segment extended if need be) has
 *     delta = R - d            (Eq. 3.3)
 *     b = sqrt(delta (2R - delta))      the half width  (Eq. 3.4)
 *     g(x) = sqrt(R^2 - x^2) - d, x in [-b, b]   the overlap (Eq. 3.2)
 * about C, O's foot on the line (x along t).  The chord [-b, b] clipped to
 * the segment, [x0, x1], is the partial contact (Figs. 3.3-3.4); empty:
 * no contact.  The force of the full contact F_n (the law at delta) is
 * scaled by gamma (Eq. 3.9), by one of the two schemes of Ch. 3.2.1:
 *   area   (Eq. 3.10)  gamma = S_p / S_f, S_p = int_{x0}^{x1} g dx, S_f the
 *                      same over [-b, b] (Eq. 3.5; Eq. 3.7 for small
 *                      delta); the force acts along G -> O, G the
 *                      centroid of S_p, through the point P where the
 *                      line G O meets the segment;
 *   width  (Eq. 3.11)  gamma = (x1 - x0) / (2b); the force acts along
 *                      P -> O, P the middle of [x0, x1] on the segment.
 *   potential  (beyond the thesis; the twin of facet.h's) below.
 * (Any other partial setting of the model, the 3D volume scheme, counts
 * as area.)  The integrals of the area scheme are taken
 * with g written without cancellation, g = (b^2 - x^2) / (sqrt(R^2 - x^2)
 * + d), by Gauss-Legendre (2 panels of 8 points; 1e-15 of S for delta <
 * R/10), so
 * gamma stays accurate as delta -> 0.  In full contact both give gamma =
 * 1, the force along nf through C.  Along collinear segments the factors
 * add up to one whatever the joints (the x-ranges tile [-b, b]), so a disk
 * crossing a joint feels the full contact force, its direction off by at
 * most the tilt of the pieces' lines of action, O(b/R) (the first moments
 * of the area pieces sum to that of S_f, their tilts cancel to first
 * order).
 *
 * Neither the area nor the width force derives from a potential: a disk
 * on a deforming block can gain energy (the area scheme 1.4 % at alpha
 * 0.5 with the linear law, the width scheme without bound on a soft
 * block: tests/unit/test_shot_impact2d.c).  The width force is continuous
 * but its uniform share per unit chord, F_n / (2b), does not vanish at
 * the chord's ends as the overlap does: on one rigid segment the work of
 * the disk's force around a small closed path near the segment's end is
 * up to 6 % of F times the path's height (area 1e-5), and a segment's end
 * entering the disk meets a finite stiffness from the first touch, set by
 * its line's overlap.  On the soft block the gain starts at the same time
 * whatever the step (0.355 ms at lambda 0.2 and 0.05, the disk still
 * going down, 8 segments touching): the scheme's, not the step's.  The potential scheme spreads
 * the law along the segment as an energy per unit length that depends only
 * on a point's distance q from O:
 *     Phi = int over the segment of w2(q) ds,
 *     w2(q) = (1/pi) int_q^R F(R - p) / sqrt(p^2 - q^2) dp
 * (F the law's branch, zero for q >= R).  w2 is the Abel inverse that
 * makes a straight line at distance d give the law's energy, int w2 dx
 * over the line = U(R - d) = int_0^delta F, so its derivative in d is the
 * law's force: a long flat (one segment or many, collinear) gives the law
 * exactly, and the segments' energies add up to the whole whatever the
 * joints (each point's energy depends on where it is only).  w2 is also
 * facet.h's surface density w(q) = F / (2 pi q) integrated across the
 * plane (the segment extruded out of the plane to a strip), so Phi and
 * its derivatives are dem_potential_polygon's integrals over the strip:
 * closed in the circle's sectors, 1D quadrature along the chords.  The
 * elastic forces are minus the gradient of Phi with respect to O, A and
 * B (the integrand vanishes where q = R, so the moving ends add nothing):
 *     on the disk   F_O = int 2 w2'(q^2) (y - O) ds
 *     on node a     F_a = -int [w2 dN_a/ds t + N_a 2 w2' (y - O)] ds
 * (N_A = 1 - tau, N_B = tau along the segment).  They sum to zero with
 * zero moment, each point pushes along the line to O (no torque on the
 * disk), and in full contact they are the law's force F_n nf through C
 * shared by C's position, as above (that case is computed so).  Damping
 * and friction act at P with gamma of the area scheme, as there.
 *
 * The force on the disk, F (normal gamma F_n n, plus friction and damping
 * from the kernel, their torque about O in T[2]), acts at P; the segment
 * gets -F at P, shared by its nodes as P = (1 - xi) A + xi B:
 *     F_A = -(1 - xi) F,   F_B = -xi F.
 * This keeps force and moment: the node forces have the resultant -F and,
 * P lying on A B, the moment of -F at P; the disk's F through P with the
 * torque r x F_t about O (r = P - O) is F at P.  The pair is in
 * equilibrium about every point.  (P lies within the segment, to the
 * order of delta/R at the chord's ends.)
 *
 * Friction and damping (Eqs. 3.54-3.62, 3.70-3.76) as in 3D: the kernel
 * with the relative velocity at P, v + w x r minus the segment's velocity
 * there, (1 - xi) V_A + xi V_B, and no spin about the normal (wn = 0).
 * The default k_t / K_n of model.h, 2/7, is the sphere's; a solid disk's
 * tangential motion at its rim has the effective mass M/3 (I = M R^2/2),
 * so its tangential spring runs at sqrt(6/7) = 0.93 of the normal
 * frequency, under the normal step of Box 3.1 (kt_ratio 1/3 would match
 * them).  Each segment keeps its own friction state: a disk moving onto
 * the next segment builds the share that segment carries from zero over
 * a slip of about mu delta / kt_ratio, small against the contact width.
 */
#ifndef DEM_CONTACT_DISK_H
#define DEM_CONTACT_DISK_H

#include "contact/facet.h"

/* The geometry of one disk/segment pair. */
typedef struct dem_seg_geom {
	double delta;  /* full contact overlap R - d (Eq. 3.3) */
	double d;      /* distance of O from the segment's line */
	double b;      /* full contact half width (Eq. 3.4) */
	double x0, x1; /* the chord [-b, b] clipped to the segment, along t from C */
	double gamma;  /* partial contact factor (Eqs. 3.9-3.11), 1 in full contact */
	double Sp, Sf; /* area scheme: overlap areas of the partial and full contact; else 0 */
	double G[2];   /* area scheme: centroid of S_p; width: P */
	double P[2];   /* point of action on the segment */
	double n[2];   /* unit direction P -> O (= G -> O): the normal force on the disk */
	double xi;     /* P = (1 - xi) A + xi B */
	int full;      /* 1: the chord lies within the segment */
	int pot;       /* 1: the potential scheme in partial contact */
	double R, L, sc;      /* the disk's radius, the segment's length, C along t from A */
	double t[2], nf[2];   /* the segment's unit tangent and normal (to the disk) */
} dem_seg_geom_t;

/* Overlap of the disk (O, R) with the segment A -> B (disk on the left):
 * returns 1 and fills g when they overlap (0 < d < R, a chord of positive
 * length on the segment), 0 otherwise.  scheme: DEM_PARTIAL_WIDTH,
 * DEM_PARTIAL_POTENTIAL (gamma, G, P and n as the area scheme, and pot set
 * in partial contact), or the area scheme for any other value. */
int dem_segment_geom(const double O[2], double R, const double A[2], const double B[2], int scheme,
                     dem_seg_geom_t *g);

/* The forces of one pair from the kernel's output o (for the pair's
 * geometry g): on the disk (F) and on the segment's nodes A, B (Fnode; the
 * three sum to zero).  For the area and width schemes, and in full
 * contact, o->F on the disk and -(1 - xi) o->F, -xi o->F on A and B; with
 * the potential scheme in partial contact, the elastic part o->Fe n is
 * replaced by minus the gradient of Phi (above) with respect to O, A and
 * B.  m: the law's exponent.  Phi, when not NULL, gets the elastic energy:
 * Phi, or gamma times the branch's energy at delta. */
void dem_segment_forces(const dem_seg_geom_t *g, const dem_contact_out_t *o, double m, double F[2],
                        double Fnode[2][2], double *Phi);

/* The overlap area of a disk of radius R with a half-plane, overlap delta
 * in [0, 2R] (Eq. 3.5: 2 R^2 atan(delta/b) - (R - delta) b), for the
 * Winkler law F = k_w S (Eq. 3.34); closed form, for tests (the pair
 * functions integrate without its cancellation at small delta). */
double dem_disk_segment_area(double R, double delta);

/* The result of one disk/segment pair at one step. */
typedef struct dem_seg_out {
	dem_seg_geom_t g;
	dem_contact_out_t c;  /* force (z = 0) on the disk, torque (about z, T[2]) about O */
	double Fnode[2][2];   /* forces on A and B (sum -c.F, moment consistent) */
} dem_seg_out_t;

/* One disk/segment pair at one step: geometry (by cm->p.partial), then
 * cm->kernel.  s: the disk (dem_sphere_t in the plane, kn from a 2D law).
 * X: the nodes A, B; V: their velocities (NULL for a segment at rest);
 * meff: the equivalent mass (Eq. 3.75; the disk's for a rigid segment).
 * Returns 1 in contact (out filled), 0 otherwise (state reset, out
 * untouched). */
int dem_contact_disk_segment(const dem_contact_model_t *cm, const dem_sphere_t *s,
                             const double X[2][2], const double (*V)[2], double meff, double dt,
                             dem_contact_state_t *st, dem_seg_out_t *out);

#endif
