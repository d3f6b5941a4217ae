/* cost.h - what a run spent: the cost line, last on stderr (DESIGN.md).
 *
 *   demdetect: cost: wall_s=0.061 cpu_s=0.060 rss_mb=48.1 detect_s=0.044 pairs=1530112
 *
 * wall_s, cpu_s and rss_mb always; then the program's phase times (*_s) and
 * work counters, in the order they were added.
 */
#ifndef DEM_CORE_COST_H
#define DEM_CORE_COST_H

#include <stdio.h>

#define DEM_COST_MAXITEM 32

typedef struct dem_cost {
	double wall0, cpu0;
	int n;
	struct {
		char name[24];
		double value;
		int is_time;
	} item[DEM_COST_MAXITEM];
} dem_cost_t;

/* Monotonic wall-clock seconds, and process CPU seconds. */
double dem_wall(void);
double dem_cpu(void);
/* Peak resident memory of the process so far, MB. */
double dem_rss_mb(void);

void dem_cost_start(dem_cost_t *c);
/* Add seconds to the phase name ("detect" prints as detect_s=). */
void dem_cost_time(dem_cost_t *c, const char *phase, double seconds);
/* Set a counter (printed as an integer when it is one). */
void dem_cost_count(dem_cost_t *c, const char *name, double value);
void dem_cost_print(const dem_cost_t *c, const char *prog, FILE *f);

#endif
