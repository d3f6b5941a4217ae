#include "core/fmt.h"

#include <stdio.h>
#include <stdlib.h>

int dem_fmt_double(char *buf, double v)
{
	int n = 0;
	for (int prec = 15; prec <= 17; prec++) {
		n = snprintf(buf, 32, "%.*g", prec, v);
		if (prec == 17 || strtod(buf, NULL) == v)
			break;
	}
	return n;
}
