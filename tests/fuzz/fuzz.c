/* fuzz.c - the fuzzing harness of the toolkit's readers (issue 21).
 *
 *   fuzz TARGET FILE...
 *
 * runs one reader over each FILE, as a program would, and exits 0 whatever
 * the reader says of the input: a bad input must give an error, never a
 * crash, a hang or a sanitizer report.  TARGET is one of
 *
 *   stream   the particle/shot/history stream reader (text, binary, gzip):
 *            every row to the trailer
 *   scene    the scene reader (YAML, units, "use:" libraries): load, the
 *            material section as demshot builds it (every hardening and
 *            rate law), the unknown-key check, the resolved dump
 *   state    the state stream reader (demshot's frames): the mesh and
 *            every frame
 *   profile  the profile stream reader (demprofile's): every pass
 *   bodies   the body stream reader (demshot's DE-only run): every row
 *
 * `make fuzz` builds it with AFL++ (afl-cc) and runs afl-fuzz on each
 * target with FILE = @@; `make check` builds it with the ordinary compiler
 * (and the sanitizers with SANITIZE=1) and replays tests/fuzz/corpus, the
 * seeds and every input a fuzz run found to crash (kept as regression
 * inputs).  No output; with DEM_FUZZ_VERBOSE set, the readers' messages on
 * standard error. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "body/frames.h"
#include "core/error.h"
#include "fe/fescene.h"
#include "fe/material.h"
#include "io/profile.h"
#include "io/scene.h"
#include "io/state.h"
#include "io/stream.h"

static int verbose;

static void said(const dem_error_t *e)
{
	if (verbose && e->code)
		fprintf(stderr, "fuzz: %s\n", e->msg);
}

static void stream(const char *path)
{
	dem_error_t e = {0};
	dem_reader_t *r = NULL;
	if (dem_reader_open(&r, path, &e) == DEM_OK) {
		double v[DEM_STREAM_MAXCOL];
		while (dem_reader_next(r, v, &e) > 0)
			;
	}
	said(&e);
	dem_reader_close(r);
}

static void scene(const char *path)
{
	dem_error_t e = {0};
	dem_scene_t *s = NULL;
	if (dem_scene_load(&s, path, &e) == DEM_OK) {
		dem_mat_t m;
		memset(&m, 0, sizeof m);
		if (dem_scene_material(s, 1, &m, &e) == DEM_OK) {
			static const char *const sections[] = {"material", NULL};
			dem_scene_check(s, sections, &e);
		}
		dem_mat_free(&m);
		FILE *f = fopen("/dev/null", "w");
		if (f) {
			dem_scene_dump(s, f);
			fclose(f);
		}
	}
	said(&e);
	dem_scene_free(s);
}

static void state(const char *path)
{
	dem_error_t e = {0};
	dem_state_reader_t *r = NULL;
	if (dem_state_reader_open(&r, path, &e) == DEM_OK) {
		dem_state_frame_t f;
		memset(&f, 0, sizeof f);
		while (dem_state_next(r, &f, &e) > 0)
			;
	}
	said(&e);
	dem_state_reader_close(r);
}

static void profile(const char *path)
{
	dem_error_t e = {0};
	dem_profile_t *ps = NULL;
	int np = 0;
	if (dem_profile_read_all(path, &ps, &np, &e) == DEM_OK) {
		for (int i = 0; i < np; i++)
			dem_profile_free(&ps[i]);
		free(ps);
	}
	said(&e);
}

static void bodies(const char *path)
{
	dem_error_t e = {0};
	dem_reader_t *r = NULL;
	if (dem_bodies_reader_open(&r, path, &e) == DEM_OK) {
		dem_body_row_t row;
		while (dem_bodies_reader_next(r, &row, &e) > 0)
			;
	}
	said(&e);
	dem_reader_close(r);
}

int main(int argc, char **argv)
{
	static const struct {
		const char *name;
		void (*run)(const char *);
	} targets[] = {
		{"stream", stream}, {"scene", scene}, {"state", state}, {"profile", profile},
		{"bodies", bodies},
	};
	if (argc < 3) {
		fprintf(stderr, "usage: fuzz stream|scene|state|profile|bodies FILE...\n");
		return 2;
	}
	verbose = getenv("DEM_FUZZ_VERBOSE") != NULL;
	for (size_t t = 0; t < sizeof targets / sizeof *targets; t++)
		if (!strcmp(argv[1], targets[t].name)) {
			for (int i = 2; i < argc; i++)
				targets[t].run(argv[i]);
			return 0;
		}
	fprintf(stderr, "fuzz: unknown target '%s'\n", argv[1]);
	return 2;
}
