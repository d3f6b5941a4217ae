/* fmt.h - numbers as text. */
#ifndef DEM_CORE_FMT_H
#define DEM_CORE_FMT_H

/* The shortest %g text (15 to 17 digits) that reads back as exactly v;
 * buf needs 32 bytes.  Returns the length. */
int dem_fmt_double(char *buf, double v);

#endif
