/* setup.h - the DE-only run a scene describes: bodies, walls, gravity
 * (dem-scene(5): the bodies, walls, contact, run and detect sections).
 *
 * One shape a scene (bodies.shape), its bodies either at the centres
 * bodies.at or bodies.count of them on a lattice filling bodies.region
 * from its bottom row up (spacing: the bounding diameter plus a gap of a
 * tenth of it), each turned by bodies.angle or, without it, by a random
 * angle from the run's generator.  Only the effects the scene names are
 * simulated: friction (contact.friction), viscous damping
 * (contact.damping), gravity (run.gravity).
 */
#ifndef DEM_BODY_SETUP_H
#define DEM_BODY_SETUP_H

#include <gsl/gsl_rng.h>

#include "body/body.h"
#include "io/scene.h"

typedef struct dem_de_setup {
	dem_shape_t shape;
	double end;      /* run.end (s) */
	long frames;     /* run.frames: frames after the start's */
} dem_de_setup_t;

/* The sections a DE-only run reads, for dem_scene_check (NULL-terminated). */
extern const char *const dem_de_sections[];

/* Read the scene into su and a new run de (dem_de_init, the bodies and
 * walls added; dem_de_start not yet called).  accuracy: DEM_ACCURACY_* of
 * core/cli.h (the sampling tolerance and lambda presets).  On failure
 * everything made is freed.  DEM_EINPUT with file:line:col for a bad
 * scene. */
int dem_de_setup_read(dem_scene_t *s, int accuracy, gsl_rng *rng, dem_de_setup_t *su,
                      dem_de_t *de, dem_error_t *e);
void dem_de_setup_free(dem_de_setup_t *su, dem_de_t *de);

/* One line naming the effects the run simulates ("gravity, friction
 * mu=0.5, viscous damping xi=0.8" or "none"), into buf. */
const char *dem_de_effects(const dem_de_t *de, char *buf, size_t len);

#endif
