/* peer-cgal.cc - the peer of demdetect in `make peers`: CGAL's
 * box_self_intersection_d on the boxes of a dem particle or box stream.
 *
 *   peer-cgal [-r REPEAT] [-k CUTOFF] [-p] FILE
 *
 * Reads FILE (a dem particles or boxes stream, text or binary records, not
 * gzip; dem-streams(5)) and builds the same closed boxes demdetect builds:
 * [x - r, x + r] on every axis for a particle, the corners for a box.  Then
 * it finds every pair of intersecting boxes REPEAT times (default 5), each
 * time on a fresh copy of the boxes in stream order (the algorithm reorders
 * its input, and a time loop rebuilds the boxes every step), storing the
 * pairs in a vector that keeps its memory from call to call, as demdetect
 * keeps its workspace.  Prints the number of pairs on stdout (with -p the
 * pairs instead, "i j" with i < j, sorted, for a check against demdetect's
 * pair stream), and last on stderr a cost line with demdetect's keys:
 *
 *   peer-cgal: cost: wall_s= cpu_s= rss_mb= read_s= detect_s=
 *              detect_warm_s= objects= pairs= repeat= cutoff=
 *
 * detect_s is the first call, detect_warm_s the median of the others: the
 * same cold and warm figures as `demdetect --repeat`.  One thread (CGAL's
 * sequential version).  Exit status 0, 1 bad input, 2 usage, 4 I/O. */

#include <CGAL/box_intersection_d.h>
#include <CGAL/Box_intersection_d/Box_with_info_d.h>

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdarg>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <utility>
#include <vector>

namespace {

const char *prog = "peer-cgal";

/* The objects as read: dim, then per object its lower and upper corner. */
struct objects {
	int dim = 0;
	std::vector<double> lo, hi;     /* dim values per object */
	size_t n = 0;
};

/* Print "peer-cgal: " and the message on stderr, exit with code. */
[[noreturn]] __attribute__((format(printf, 2, 3)))
void fail(int code, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	std::fprintf(stderr, "%s: ", prog);
	std::vfprintf(stderr, fmt, ap);
	std::fputc('\n', stderr);
	va_end(ap);
	std::exit(code);
}

double wall_now()
{
	return std::chrono::duration<double>(
		std::chrono::steady_clock::now().time_since_epoch()).count();
}

double cpu_now()
{
	return (double)std::clock() / CLOCKS_PER_SEC;
}

/* One header line without its newline; false at end of file. */
bool get_line(FILE *f, std::string &s)
{
	s.clear();
	int c;
	while ((c = std::getc(f)) != EOF && c != '\n')
		s.push_back((char)c);
	return c != EOF || !s.empty();
}

/* Read a particles or boxes stream (dem-streams(5)) into o. */
void read_stream(const char *path, objects &o)
{
	FILE *f = std::fopen(path, "rb");
	if (!f)
		fail(4, "%s: %s", path, std::strerror(errno));
	std::string line, kind, columns, format;
	long lineno = 0;
	if (!get_line(f, line) || line.compare(0, 6, "# dem ") != 0)
		fail(1, "%s:1: not a dem stream (gzip is not read here: gunzip it first)", path);
	kind = line.substr(6, line.find(' ', 6) - 6);
	if (kind != "particles" && kind != "boxes")
		fail(1, "%s:1: a %s stream; expected particles or boxes", path, kind.c_str());
	lineno = 1;
	for (;;) {
		if (!get_line(f, line))
			fail(1, "%s: truncated stream: it ends in its header", path);
		lineno++;
		if (line == "# data")
			break;
		if (line.compare(0, 6, "# dim ") == 0)
			o.dim = std::atoi(line.c_str() + 6);
		else if (line.compare(0, 10, "# columns ") == 0)
			columns = line.substr(10);
		else if (line.compare(0, 9, "# format ") == 0)
			format = line.substr(9);
	}
	if (o.dim < 1 || o.dim > 3)
		fail(1, "%s: no '# dim' line of 1, 2 or 3 in the header", path);
	/* the columns: name, byte offset in a binary record, and type */
	std::vector<std::string> names, types, units;
	for (size_t p = 0; p < columns.size();) {
		size_t q = columns.find(' ', p);
		if (q == std::string::npos)
			q = columns.size();
		std::string c = columns.substr(p, q - p);
		if (!c.empty()) {
			size_t a = c.find(':'), b = c.find(':', a + 1);
			if (a == std::string::npos || b == std::string::npos)
				fail(1, "%s: bad column '%s'", path, c.c_str());
			names.push_back(c.substr(0, a));
			types.push_back(c.substr(a + 1, b - a - 1));
			units.push_back(c.substr(b + 1));
		}
		p = q + 1;
	}
	size_t ncol = names.size(), recsize = 0;
	std::vector<size_t> off(ncol);
	for (size_t k = 0; k < ncol; k++) {
		off[k] = recsize;
		recsize += types[k] == "u32" ? 4 : 8;
	}
	bool particles = kind == "particles";
	static const char *const pn[] = {"x", "y", "z"};
	static const char *const ln[] = {"xlo", "ylo", "zlo"};
	static const char *const hn[] = {"xhi", "yhi", "zhi"};
	int ci[3], hi[3], cr = -1;
	auto col = [&](const char *name) {
		for (size_t k = 0; k < ncol; k++)
			if (names[k] == name) {
				if (types[k] != "f64" || units[k] != "m")
					fail(1, "%s: column %s is not f64 in m", path, name);
				return (int)k;
			}
		fail(1, "%s: no column '%s'", path, name);
	};
	for (int d = 0; d < o.dim; d++) {
		ci[d] = col(particles ? pn[d] : ln[d]);
		hi[d] = particles ? 0 : col(hn[d]);
	}
	if (particles)
		cr = col("r");

	std::vector<double> v(ncol);
	auto add = [&]() {
		if (particles && !(v[cr] >= 0))
			fail(1, "%s: row %zu: radius %g is not a length", path, o.n + 1, v[cr]);
		for (int d = 0; d < o.dim; d++) {
			double lo = particles ? v[ci[d]] - v[cr] : v[ci[d]];
			double up = particles ? v[ci[d]] + v[cr] : v[hi[d]];
			o.lo.push_back(lo);
			o.hi.push_back(up);
		}
		o.n++;
	};
	if (format == "binary") {
		std::vector<unsigned char> rec(recsize);
		for (;;) {
			unsigned char b[4];
			if (std::fread(b, 1, 4, f) != 4)
				fail(1, "%s: truncated stream: it ends inside its records", path);
			uint32_t count = b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
			if (count == 0)
				break;
			for (uint32_t k = 0; k < count; k++) {
				if (std::fread(rec.data(), 1, recsize, f) != recsize)
					fail(1, "%s: truncated stream: it ends inside a block", path);
				for (size_t c = 0; c < ncol; c++) {
					uint64_t u = 0;
					if (types[c] != "f64")
						continue;
					for (int i = 7; i >= 0; i--)
						u = u << 8 | rec[off[c] + (size_t)i];
					std::memcpy(&v[c], &u, 8);
				}
				add();
			}
		}
	} else if (format == "text") {
		for (;;) {
			if (!get_line(f, line))
				fail(1, "%s: truncated stream: no trailer '# end N'", path);
			lineno++;
			if (line.empty())
				continue;
			if (line[0] == '#')
				break;
			const char *s = line.c_str();
			for (size_t c = 0; c < ncol; c++) {
				char *end;
				v[c] = std::strtod(s, &end);
				if (end == s)
					fail(1, "%s:%ld: too few numbers", path, lineno);
				s = end;
			}
			add();
		}
	} else {
		fail(1, "%s: '# format %s' is neither text nor binary", path, format.c_str());
	}
	if (format == "binary" && !get_line(f, line))
		fail(1, "%s: truncated stream: no trailer '# end N'", path);
	if (line.compare(0, 6, "# end ") != 0 || std::strtoul(line.c_str() + 6, nullptr, 10) != o.n)
		fail(1, "%s: the trailer does not count the %zu rows read", path, o.n);
	std::fclose(f);
}

template <int D>
using box_t = CGAL::Box_intersection_d::Box_with_info_d<double, D, uint32_t>;

/* Detect repeat times; times[k] the seconds of call k; pairs of the last. */
template <int D>
void detect(objects &o, int repeat, std::ptrdiff_t cutoff,
	    std::vector<double> &times, std::vector<std::pair<uint32_t, uint32_t>> &pairs)
{
	std::vector<box_t<D>> boxes, work;
	boxes.reserve(o.n);
	for (size_t i = 0; i < o.n; i++) {
		double lo[D], hi[D];
		for (int d = 0; d < D; d++) {
			lo[d] = o.lo[D * i + d];
			hi[d] = o.hi[D * i + d];
		}
		boxes.emplace_back(lo, hi, (uint32_t)i);
	}
	std::vector<double>().swap(o.lo);     /* the boxes hold them now */
	std::vector<double>().swap(o.hi);
	auto report = [&pairs](const box_t<D> &a, const box_t<D> &b) {
		uint32_t i = a.info(), j = b.info();
		pairs.emplace_back(std::min(i, j), std::max(i, j));
	};
	for (int k = 0; k < repeat; k++) {
		work = boxes;                   /* stream order again, not timed */
		pairs.clear();
		double t0 = wall_now();
		CGAL::box_self_intersection_d(work.begin(), work.end(), report, cutoff,
					      CGAL::Box_intersection_d::CLOSED);
		times.push_back(wall_now() - t0);
	}
}

void usage()
{
	std::fprintf(stderr, "Usage: %s [-r REPEAT] [-k CUTOFF] [-p] FILE\n", prog);
	std::exit(2);
}

} // namespace

int main(int argc, char **argv)
{
	int repeat = 5, opt;
	long cutoff = 10;               /* CGAL's default */
	bool print = false;
	while ((opt = getopt(argc, argv, "r:k:p")) != -1) {
		char *end;
		switch (opt) {
		case 'r':
			repeat = (int)std::strtol(optarg, &end, 10);
			if (*end || repeat < 1)
				usage();
			break;
		case 'k':
			cutoff = std::strtol(optarg, &end, 10);
			if (*end || cutoff < 1)
				usage();
			break;
		case 'p':
			print = true;
			break;
		default:
			usage();
		}
	}
	if (optind != argc - 1)
		usage();

	double w0 = wall_now(), c0 = cpu_now();
	objects o;
	read_stream(argv[optind], o);
	double read_s = wall_now() - w0;
	if (o.n > UINT32_MAX)
		fail(1, "%s: more than 2^32-1 objects", argv[optind]);

	std::vector<double> times;
	std::vector<std::pair<uint32_t, uint32_t>> pairs;
	if (o.dim == 2)
		detect<2>(o, repeat, cutoff, times, pairs);
	else if (o.dim == 3)
		detect<3>(o, repeat, cutoff, times, pairs);
	else
		detect<1>(o, repeat, cutoff, times, pairs);

	if (print) {
		std::sort(pairs.begin(), pairs.end());
		for (const auto &p : pairs)
			std::printf("%u %u\n", p.first, p.second);
	} else {
		std::printf("%zu\n", pairs.size());
	}
	if (std::fflush(stdout) != 0 || std::ferror(stdout))
		fail(4, "stdout: %s", std::strerror(errno));

	std::vector<double> warm(times.begin() + 1, times.end());
	std::sort(warm.begin(), warm.end());
	size_t m = warm.size();
	double warm_s = m == 0 ? times[0] : m % 2 ? warm[m / 2] : 0.5 * (warm[m / 2 - 1] + warm[m / 2]);
	struct rusage ru;
	getrusage(RUSAGE_SELF, &ru);
	std::fprintf(stderr, "%s: cost: wall_s=%.3f cpu_s=%.3f rss_mb=%.1f read_s=%.6f "
		     "detect_s=%.6f detect_warm_s=%.6f objects=%zu pairs=%zu repeat=%d cutoff=%ld\n",
		     prog, wall_now() - w0, cpu_now() - c0, ru.ru_maxrss / 1024.0, read_s,
		     times[0], warm_s, o.n, pairs.size(), repeat, cutoff);
	return 0;
}
