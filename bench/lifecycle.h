/* sepax benchmarks — the cost of waking and destroying in a world of
 * sleeping bodies (bench/lifecycle.c). */
#ifndef SEPAX_BENCH_LIFECYCLE_H
#define SEPAX_BENCH_LIFECYCLE_H

/** Runs the wake and destroy scaling figures (smoke: a small world, seconds),
 *  prints them and writes lifecycle.csv into out_dir. Returns the number of
 *  failed checks (0 when every figure's world ended as expected). */
int bench_lifecycle_run(const char *out_dir, int smoke);

#endif /* SEPAX_BENCH_LIFECYCLE_H */
