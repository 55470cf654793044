/* sepax tests — replays the fuzzing corpus, so every input the fuzzers once
 * found interesting (and every crash they found, once fixed) keeps being
 * checked by `make test`, with gcc and no libFuzzer.
 *
 * The harness sources in fuzz/ are compiled into this program: each is
 * included with LLVMFuzzerTestOneInput renamed to its own entry point, and
 * FZ_FAIL (the harnesses' invariant report) turned into a cmocka failure
 * naming the corpus file. Every file of every fuzz/corpus/<harness>/
 * directory (found from the repository root, the current directory of
 * `make test`) goes through every harness: any byte string is a valid input
 * to each of them, and the cross-feeding costs little. Files are replayed in
 * name order, so a run is deterministic. */
#define _POSIX_C_SOURCE 200809L

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test_support.h"

/* The corpus file being replayed, for the failure message. */
static char replay_current[512];

static void replay_fail(const char *expr, const char *file, int line) {
    fail_msg("%s: fuzz invariant broken: %s (%s:%d)", replay_current, expr, file, line);
}
#define FZ_FAIL(expr, file, line) replay_fail(expr, file, line)

#define LLVMFuzzerTestOneInput replay_hull_one
#include "../fuzz/fuzz_hull.c"
#undef LLVMFuzzerTestOneInput
#define LLVMFuzzerTestOneInput replay_collide_one
#include "../fuzz/fuzz_collide.c"
#undef LLVMFuzzerTestOneInput
#define LLVMFuzzerTestOneInput replay_query_one
#include "../fuzz/fuzz_query.c"
#undef LLVMFuzzerTestOneInput
#define LLVMFuzzerTestOneInput replay_compound_one
#include "../fuzz/fuzz_compound.c"
#undef LLVMFuzzerTestOneInput
#define LLVMFuzzerTestOneInput replay_decompose_one
#include "../fuzz/fuzz_decompose.c"
#undef LLVMFuzzerTestOneInput
#define LLVMFuzzerTestOneInput replay_world_one
#include "../fuzz/fuzz_world.c"
#undef LLVMFuzzerTestOneInput
#define LLVMFuzzerTestOneInput replay_distance_one
#include "../fuzz/fuzz_distance.c"
#undef LLVMFuzzerTestOneInput

typedef int replay_fn(const uint8_t *data, size_t size);

#define REPLAY_CORPUS_ROOT "fuzz/corpus"
#define REPLAY_MAX_FILES 512
#define REPLAY_MAX_BYTES 4096 /* the fuzzers run with -max_len=1024 */

static const char *const replay_corpora[] = {"hull",      "collide", "query",   "compound",
                                             "decompose", "world",   "distance"};

static int replay_cmp_names(const void *a, const void *b) {
    return strcmp(*(const char *const *)a, *(const char *const *)b);
}

/* Feeds every file of fuzz/corpus/<dir>/ to fn; returns the file count. */
static int replay_dir(const char *dir, replay_fn *fn) {
    static char names[REPLAY_MAX_FILES][256];
    static const char *order[REPLAY_MAX_FILES];
    static uint8_t bytes[REPLAY_MAX_BYTES];
    char path[512];
    DIR *d;
    struct dirent *e;
    int count = 0, i;
    snprintf(path, sizeof path, "%s/%s", REPLAY_CORPUS_ROOT, dir);
    d = opendir(path);
    if (d == NULL)
        fail_msg("cannot open the corpus directory %s (run from the repository root)", path);
    while ((e = readdir(d)) != NULL) {
        if (e->d_name[0] == '.') continue;
        assert_true(count < REPLAY_MAX_FILES);
        assert_true(strlen(e->d_name) < sizeof names[0]);
        strcpy(names[count], e->d_name);
        order[count] = names[count];
        ++count;
    }
    closedir(d);
    qsort(order, (size_t)count, sizeof order[0], replay_cmp_names);
    for (i = 0; i < count; ++i) {
        FILE *f;
        size_t n;
        snprintf(replay_current, sizeof replay_current, "%s/%s/%s", REPLAY_CORPUS_ROOT, dir,
                 order[i]);
        f = fopen(replay_current, "rb");
        if (f == NULL) fail_msg("cannot read %s", replay_current);
        n = fread(bytes, 1, sizeof bytes, f);
        assert_true(feof(f)); /* no corpus file is larger than REPLAY_MAX_BYTES */
        fclose(f);
        assert_int_equal(fn(bytes, n), 0);
    }
    return count;
}

/* Every corpus through one harness; each harness must have its own
 * non-empty corpus, so a missing directory fails instead of passing empty. */
static void replay_all(replay_fn *fn, const char *own) {
    size_t k;
    int own_count = -1;
    for (k = 0; k < sizeof replay_corpora / sizeof replay_corpora[0]; ++k) {
        int n = replay_dir(replay_corpora[k], fn);
        if (strcmp(replay_corpora[k], own) == 0) own_count = n;
    }
    assert_true(own_count > 0);
}

static void hull_harness_passes_every_corpus_file(void **state) {
    (void)state;
    replay_all(replay_hull_one, "hull");
}

static void collide_harness_passes_every_corpus_file(void **state) {
    (void)state;
    replay_all(replay_collide_one, "collide");
}

static void query_harness_passes_every_corpus_file(void **state) {
    (void)state;
    replay_all(replay_query_one, "query");
}

static void compound_harness_passes_every_corpus_file(void **state) {
    (void)state;
    replay_all(replay_compound_one, "compound");
}

static void decompose_harness_passes_every_corpus_file(void **state) {
    (void)state;
    replay_all(replay_decompose_one, "decompose");
}

static void world_harness_passes_every_corpus_file(void **state) {
    (void)state;
    replay_all(replay_world_one, "world");
}

static void distance_harness_passes_every_corpus_file(void **state) {
    (void)state;
    replay_all(replay_distance_one, "distance");
}

/* The empty input and a run of every byte value decode to something in each
 * harness (the reader pads with zeros), so short or odd files never crash. */
static void every_harness_accepts_empty_and_all_byte_values(void **state) {
    uint8_t all[256];
    int i;
    (void)state;
    for (i = 0; i < 256; ++i)
        all[i] = (uint8_t)i;
    snprintf(replay_current, sizeof replay_current, "(built-in input)");
    assert_int_equal(replay_hull_one(NULL, 0), 0);
    assert_int_equal(replay_collide_one(NULL, 0), 0);
    assert_int_equal(replay_query_one(NULL, 0), 0);
    assert_int_equal(replay_compound_one(NULL, 0), 0);
    assert_int_equal(replay_decompose_one(NULL, 0), 0);
    assert_int_equal(replay_world_one(NULL, 0), 0);
    assert_int_equal(replay_distance_one(NULL, 0), 0);
    for (i = 0; i < 256; i += 7) {
        assert_int_equal(replay_hull_one(all + i, (size_t)(256 - i)), 0);
        assert_int_equal(replay_collide_one(all + i, (size_t)(256 - i)), 0);
        assert_int_equal(replay_query_one(all + i, (size_t)(256 - i)), 0);
        assert_int_equal(replay_compound_one(all + i, (size_t)(256 - i)), 0);
        assert_int_equal(replay_decompose_one(all + i, (size_t)(256 - i)), 0);
        assert_int_equal(replay_world_one(all + i, (size_t)(256 - i)), 0);
        assert_int_equal(replay_distance_one(all + i, (size_t)(256 - i)), 0);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(hull_harness_passes_every_corpus_file),
        cmocka_unit_test(collide_harness_passes_every_corpus_file),
        cmocka_unit_test(query_harness_passes_every_corpus_file),
        cmocka_unit_test(compound_harness_passes_every_corpus_file),
        cmocka_unit_test(decompose_harness_passes_every_corpus_file),
        cmocka_unit_test(world_harness_passes_every_corpus_file),
        cmocka_unit_test(distance_harness_passes_every_corpus_file),
        cmocka_unit_test(every_harness_accepts_empty_and_all_byte_values),
    };
    return cmocka_run_group_tests_name("fuzz_replay", tests, sx_test_group_setup,
                                       sx_test_group_teardown);
}
