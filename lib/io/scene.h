/* scene.h - the scene: one YAML file describing a whole job.
 *
 * Each program reads the sections it needs through typed getters that take
 * a dotted key ("pack.radius.min"), the expected dimension, the range and the
 * default.  Every getter records the value it resolved, so --dump-scene can
 * print the scene with every default filled in, and marks the key as known,
 * so dem_scene_check() can reject unknown keys in the sections a program
 * read.  Errors carry file:line:column (libyaml marks, 1-based) and say the
 * expected form.  Command-line options enter through dem_scene_override() and
 * are validated by the same getters ("command line: --density: ...").
 */
#ifndef DEM_IO_SCENE_H
#define DEM_IO_SCENE_H

#include <float.h>
#include <stdio.h>

#include "core/error.h"
#include "core/units.h"

typedef struct dem_scene dem_scene_t;

/* Load a scene from path; path NULL gives an empty scene (every value at its
 * default).  Syntax errors are DEM_EINPUT with file:line:col; an unreadable
 * file is DEM_EIO with strerror.
 *
 * A section with a library folder (material: share/materials, shot:
 * share/shots; see core/share.h for share) may say "use: NAME": the file
 * NAME.yaml there (or NAME itself, relative to the scene's folder, when it
 * has a '/' or ends in .yaml) is merged into the section as it loads: the
 * scene's keys win, mappings merge key by key, sequences and scalars are
 * replaced whole.  Errors in its values name that file; dem_scene_check
 * passes over its keys that no getter asked for (a library may hold the
 * data of several laws); --dump-scene shows the use: line first in its
 * section. */
int dem_scene_load(dem_scene_t **s, const char *path, dem_error_t *e);
void dem_scene_free(dem_scene_t *s);

/* Set key to the scalar text (as if written in the scene), from the option
 * named origin (e.g. "--density").  Overrides a value from the file. */
int dem_scene_override(dem_scene_t *s, const char *key, const char *text,
		       const char *origin, dem_error_t *e);

struct dem_override;

/* Apply the n overrides of ov in order (see dem_common_t in core/cli.h). */
int dem_scene_override_all(dem_scene_t *s, const struct dem_override *ov,
			   int n, dem_error_t *e);

struct dem_common;

/* A program's scene: the file its common options name (-s FILE; none:
 * every key takes its default) with the keys its options set applied
 * over it (dem_scene_load, then dem_scene_override_all). */
int dem_scene_open(dem_scene_t **s, const struct dem_common *m, dem_error_t *e);

/* Is key present (in the file or by override)? */
int dem_scene_has(const dem_scene_t *s, const char *key);

/* Number of items of key's sequence (or of the comma-separated items of a
 * scalar vector such as "1, 2 mm"), for vectors whose length the scene
 * chooses (tables); -1 when the key is absent, 0 for a mapping.  Read the
 * items with dem_scene_vector(). */
int dem_scene_length(const dem_scene_t *s, const char *key);

/* Getters.  An absent key yields the default.  A present key must have the
 * right type, unit and range [min, max] (inclusive), or the getter fails with
 * DEM_EINPUT and a message naming file:line:col, the key and the expected
 * form. */
/* For quantities, HUGE_VAL and -HUGE_VAL are open bounds, and a min of
 * DEM_SCENE_GT0 (the smallest positive double) asks for a value greater than
 * 0, so messages read "in (0, 1]" or "greater than 0 m".  A non-finite
 * default (NAN) and a NULL default (vector, string) mean "no default": the
 * getter leaves out as it is (NAN, NULL) and --dump-scene leaves the key
 * out.  A vector may also be one scalar, "[1, 2] mm" or "1, 2" (handy on the
 * command line). */
#define DEM_SCENE_GT0 DBL_TRUE_MIN

int dem_scene_quantity(dem_scene_t *s, const char *key, dem_dim_t dim,
		       double def, double min, double max, double *out,
		       dem_error_t *e);
int dem_scene_int(dem_scene_t *s, const char *key, long def, long min,
		  long max, long *out, dem_error_t *e);
int dem_scene_bool(dem_scene_t *s, const char *key, int def, int *out,
		   dem_error_t *e);
/* One of the NULL-terminated names in choices; *out is its index. */
int dem_scene_choice(dem_scene_t *s, const char *key,
		     const char *const *choices, int def, int *out,
		     dem_error_t *e);
/* A flow or block sequence of exactly n quantities ([1 mm, 2 mm, 3 mm]). */
int dem_scene_vector(dem_scene_t *s, const char *key, dem_dim_t dim, int n,
		     const double *def, double min, double max, double *out,
		     dem_error_t *e);
/* A free string; *out stays valid until dem_scene_free. */
int dem_scene_string(dem_scene_t *s, const char *key, const char *def,
		     const char **out, dem_error_t *e);

/* Report a problem the program found in key's value after a getter read it
 * (e.g. periodic axes other than x, y, z): fills e with DEM_EINPUT and
 * "WHERE: KEY: message", WHERE being the value's file:line:col or
 * "command line: OPTION"; without WHERE when the key is absent (the value
 * was the program's default).  Returns DEM_EINPUT. */
int dem_scene_error(const dem_scene_t *s, const char *key, dem_error_t *e,
		    const char *fmt, ...) __attribute__((format(printf, 4, 5)));

/* Reject keys, under the given top-level sections (NULL-terminated), that
 * no getter asked for; and reject top-level sections that are not in the
 * toolkit's list of known sections.  The first unknown key is reported with
 * file:line:col and the keys that are allowed there. */
int dem_scene_check(const dem_scene_t *s, const char *const *sections,
		    dem_error_t *e);

/* Print the resolved scene (every value a getter resolved, defaults
 * included, in SI units with the unit written) as YAML. */
void dem_scene_dump(const dem_scene_t *s, FILE *f);

#endif
