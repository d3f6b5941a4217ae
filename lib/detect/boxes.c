/* boxes.c - the detectors' shared types: workspaces, boxes and pair
 * lists (see boxes.h). */
#include "detect/boxes.h"

#include <stdlib.h>
#include <string.h>

struct dem_detect_ws {
	void *buf[DEM_DETECT_WS_SLOTS];
	size_t cap[DEM_DETECT_WS_SLOTS];
};

dem_detect_ws_t *dem_detect_ws_new(void)
{
	return calloc(1, sizeof(dem_detect_ws_t));
}

void dem_detect_ws_free(dem_detect_ws_t *ws)
{
	if (!ws)
		return;
	for (int k = 0; k < DEM_DETECT_WS_SLOTS; k++)
		free(ws->buf[k]);
	free(ws);
}

/* A buffer that must grow gets 1/8 more than asked, so a set that grows a
 * little from step to step does not reallocate every step.  Buffers start
 * on a cache line, so records of 32 or 64 bytes never straddle two. */
void *dem_detect_ws_get(dem_detect_ws_t *ws, int slot, size_t bytes)
{
	enum { LINE = 64 };

	if (bytes == 0)
		bytes = 1;      /* a buffer all the same, not NULL */
	if (bytes <= ws->cap[slot])
		return ws->buf[slot];
	free(ws->buf[slot]);
	size_t cap = (bytes + bytes / 8 + LINE - 1) / LINE * LINE;
	ws->buf[slot] = aligned_alloc(LINE, cap);
	ws->cap[slot] = ws->buf[slot] ? cap : 0;
	return ws->buf[slot];
}

int dem_boxes_alloc(dem_boxes_t *b, int dim, size_t n)
{
	memset(b, 0, sizeof *b);
	b->dim = dim;
	b->n = n;
	double *block = malloc((n ? n : 1) * 2 * (size_t)dim * sizeof *block);
	if (!block)
		return DEM_EIO;
	for (int d = 0; d < dim; d++) {
		b->lo[d] = block + (2 * (size_t)d) * n;
		b->hi[d] = block + (2 * (size_t)d + 1) * n;
	}
	return DEM_OK;
}

void dem_boxes_free(dem_boxes_t *b)
{
	free(b->lo[0]);         /* the start of the one block */
	memset(b, 0, sizeof *b);
}

void dem_pairs_init(dem_pairs_t *p)
{
	memset(p, 0, sizeof *p);
}

void dem_pairs_free(dem_pairs_t *p)
{
	free(p->p);
	memset(p, 0, sizeof *p);
}

int dem_pairs_grow(dem_pairs_t *p)
{
	size_t cap = p->cap ? p->cap * 2 : 1024;
	dem_pair_t *q = realloc(p->p, cap * sizeof *q);
	if (!q) {
		p->nomem = 1;
		return DEM_EIO;
	}
	p->p = q;
	p->cap = cap;
	return DEM_OK;
}

/* LSD radix sort by j then by i, 16 bits a pass, over the bits in use. */
static int pair_cmp(const void *a, const void *b)
{
	const dem_pair_t *x = a, *y = b;
	if (x->i != y->i)
		return x->i < y->i ? -1 : 1;
	return x->j < y->j ? -1 : x->j > y->j;
}

int dem_pairs_sort(dem_pairs_t *p)
{
	enum { R = 16, B = 1 << R };
	uint32_t maxv = 0;

	if (p->n < 2)
		return DEM_OK;
	/* a short list: the radix passes' 2^16 counters would cost more than
	 * sorting it (a DE run sorts its few hundred pairs every step) */
	if (p->n < 4096) {
		qsort(p->p, p->n, sizeof *p->p, pair_cmp);
		return DEM_OK;
	}
	for (size_t k = 0; k < p->n; k++)
		maxv = p->p[k].j > maxv ? p->p[k].j : maxv;
	dem_pair_t *tmp = malloc(p->n * sizeof *tmp);
	size_t *count = malloc(B * sizeof *count);
	if (!tmp || !count) {
		free(tmp);
		free(count);
		return DEM_EIO;
	}
	dem_pair_t *src = p->p, *dst = tmp;
	for (int field = 1; field >= 0; field--) {
		for (int shift = 0; shift < 32 && (maxv >> shift); shift += R) {
			memset(count, 0, B * sizeof *count);
			for (size_t k = 0; k < p->n; k++) {
				uint32_t v = field ? src[k].j : src[k].i;
				count[(v >> shift) & (B - 1)]++;
			}
			size_t sum = 0;
			for (size_t c = 0; c < B; c++) {
				size_t t = count[c];
				count[c] = sum;
				sum += t;
			}
			for (size_t k = 0; k < p->n; k++) {
				uint32_t v = field ? src[k].j : src[k].i;
				dst[count[(v >> shift) & (B - 1)]++] = src[k];
			}
			dem_pair_t *t = src;
			src = dst;
			dst = t;
		}
	}
	if (src != p->p)
		memcpy(p->p, src, p->n * sizeof *src);
	free(tmp);
	free(count);
	return DEM_OK;
}
