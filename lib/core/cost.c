#include "core/cost.h"

#include <math.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

double dem_wall(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

double dem_cpu(void)
{
	struct timespec t;
	clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

double dem_rss_mb(void)
{
	struct rusage ru;
	if (getrusage(RUSAGE_SELF, &ru) != 0)
		return 0;
	return (double)ru.ru_maxrss / 1024.0;   /* Linux reports KiB */
}

void dem_cost_start(dem_cost_t *c)
{
	memset(c, 0, sizeof *c);
	c->wall0 = dem_wall();
	c->cpu0 = dem_cpu();
}

static int slot(dem_cost_t *c, const char *name, int is_time)
{
	for (int i = 0; i < c->n; i++)
		if (strcmp(c->item[i].name, name) == 0)
			return i;
	if (c->n == DEM_COST_MAXITEM)
		return -1;
	int i = c->n++;
	snprintf(c->item[i].name, sizeof c->item[i].name, "%s", name);
	c->item[i].value = 0;
	c->item[i].is_time = is_time;
	return i;
}

void dem_cost_time(dem_cost_t *c, const char *phase, double seconds)
{
	int i = slot(c, phase, 1);
	if (i >= 0)
		c->item[i].value += seconds;
}

void dem_cost_count(dem_cost_t *c, const char *name, double value)
{
	int i = slot(c, name, 0);
	if (i >= 0)
		c->item[i].value = value;
}

void dem_cost_print(const dem_cost_t *c, const char *prog, FILE *f)
{
	fprintf(f, "%s: cost: wall_s=%.3f cpu_s=%.3f rss_mb=%.1f", prog,
		dem_wall() - c->wall0, dem_cpu() - c->cpu0, dem_rss_mb());
	for (int i = 0; i < c->n; i++) {
		double v = c->item[i].value;
		if (c->item[i].is_time)
			fprintf(f, " %s_s=%.4f", c->item[i].name, v);
		else if (v == floor(v) && fabs(v) < 9e15)
			fprintf(f, " %s=%.0f", c->item[i].name, v);
		else
			fprintf(f, " %s=%.6g", c->item[i].name, v);
	}
	fputc('\n', f);
	fflush(f);
}
