# sepax — build, test, install.
#
#   make                      build/libsepax.a and build/libsepax.so
#   make test                 build and run every cmocka test (float build)
#   make test SX_REAL=double  the same with sx_real = double
#   make test SAN=1           the tests under AddressSanitizer + UBSan
#   make test SAN=thread      the tests under ThreadSanitizer (test_threads
#                             runs worlds on two threads)
#   make test SIMD=0          the float build without its SSE loops (portable C)
#   make stress               the hostile scenes with the 100,000-step long run
#   make determinism          the determinism hash at -O0, -O2 and -O3 must agree
#   make bench                benchmarks (installs the peers it compares with)
#   make install PREFIX=/usr/local
#   make clean
#
# Variants build out of tree: the default float build in build/, the others
# in build/<variant>/ (double, san, tsan, double-san, ...), so they never mix
# objects.
# Missing dependencies are installed by scripts/deps.sh (Debian packages when
# run as root, otherwise a message naming the package).

SX_REAL ?= float
SAN ?= 0
SIMD ?= 1
PREFIX ?= /usr/local

CC ?= cc
CXX ?= c++

VARIANT :=
DEFS :=
ifeq ($(SX_REAL),double)
  VARIANT := double
  DEFS += -DSX_DOUBLE
else ifneq ($(SX_REAL),float)
  $(error SX_REAL must be float or double)
endif
ifeq ($(SIMD),0)
  VARIANT := $(if $(VARIANT),$(VARIANT)-nosimd,nosimd)
  DEFS += -DSX_NO_SIMD
endif
SANFLAGS :=
ifeq ($(SAN),1)
  VARIANT := $(if $(VARIANT),$(VARIANT)-san,san)
  SANFLAGS := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
else ifeq ($(SAN),thread)
  VARIANT := $(if $(VARIANT),$(VARIANT)-tsan,tsan)
  SANFLAGS := -fsanitize=thread -fno-omit-frame-pointer
else ifneq ($(SAN),0)
  $(error SAN must be 0, 1 or thread)
endif
OUT := build$(if $(VARIANT),/$(VARIANT))

# Strict flags for our code. -ffp-contract=off keeps results bit-identical
# across optimisation levels (no fused multiply-add contraction).
# -fno-semantic-interposition: the library's calls to its own functions stay
# direct (and inlinable) although the objects are -fPIC for libsepax.so; a
# program cannot interpose sepax's internal symbols.
WARNINGS := -Wall -Wextra -pedantic -Wshadow -Wmissing-prototypes -Wstrict-prototypes \
            -Wold-style-definition -Wdouble-promotion -Wfloat-conversion -Wundef \
            -Wpointer-arith -Wvla -Wcast-qual -Wwrite-strings -Werror
OPT ?= -O2 -g
BASE_CFLAGS := -std=c99 $(OPT) -ffp-contract=off -fPIC -fno-semantic-interposition $(WARNINGS) $(SANFLAGS) $(DEFS) \
               -Iinclude -MMD -MP
CFLAGS_ALL = $(BASE_CFLAGS) $(CFLAGS)
LDLIBS_ALL := -lm

SRCS := $(sort $(wildcard src/*.c))
OBJS := $(SRCS:src/%.c=$(OUT)/obj/src/%.o)
LIB_A := $(OUT)/libsepax.a
LIB_SO := $(OUT)/libsepax.so

TEST_SRCS := $(sort $(wildcard tests/test_*.c))
TEST_SUPPORT := $(sort $(wildcard tests/support/*.c))
TEST_SUPPORT_OBJS := $(TEST_SUPPORT:tests/support/%.c=$(OUT)/obj/tests/support/%.o)
TEST_BINS := $(TEST_SRCS:tests/%.c=$(OUT)/tests/%)
CMOCKA_CFLAGS = $(shell pkg-config --cflags cmocka 2>/dev/null)
CMOCKA_LIBS = $(shell pkg-config --libs cmocka 2>/dev/null || echo -lcmocka)

.PHONY: all lib test test-run check-headers readme-example sample-pyramid deps-test deps-bench install clean bench \
        bench-smoke format format-check
.DEFAULT_GOAL := all
.SECONDARY:

all: lib
lib: $(LIB_A) $(LIB_SO)

$(OUT)/obj/src/%.o: src/%.c | $(OUT)/obj/src
	$(CC) $(CFLAGS_ALL) -c $< -o $@

$(LIB_A): $(OBJS)
	rm -f $@
	ar rcs $@ $^

$(LIB_SO): $(OBJS)
	$(CC) -shared $(SANFLAGS) -o $@ $^ $(LDLIBS_ALL)

$(OUT)/obj/src $(OUT)/obj/tests $(OUT)/obj/tests/support $(OUT)/tests $(OUT)/obj/bench $(OUT)/bench:
	mkdir -p $@

# ---- tests ------------------------------------------------------------------

deps-test:
	@sh scripts/deps.sh cmocka

$(OUT)/obj/tests/support/%.o: tests/support/%.c | $(OUT)/obj/tests/support deps-test
	$(CC) $(CFLAGS_ALL) $(CMOCKA_CFLAGS) -Itests/support -c $< -o $@

$(OUT)/obj/tests/%.o: tests/%.c | $(OUT)/obj/tests deps-test
	$(CC) $(CFLAGS_ALL) $(CMOCKA_CFLAGS) -Itests/support -c $< -o $@

$(OUT)/tests/%: $(OUT)/obj/tests/%.o $(TEST_SUPPORT_OBJS) $(LIB_A) | $(OUT)/tests
	$(CC) $(SANFLAGS) -o $@ $< $(TEST_SUPPORT_OBJS) $(LIB_A) $(CMOCKA_LIBS) $(LDLIBS_ALL) $(TEST_LDLIBS)

# tests/test_threads.c runs worlds on POSIX threads.
$(OUT)/obj/tests/test_threads.o: CFLAGS += -pthread
$(OUT)/tests/test_threads: TEST_LDLIBS := -pthread

# Public headers must compile as C++ too.
check-headers:
	@echo "sepax: compiling the public headers as C++"
	@printf '#include <sepax/sepax.h>\nint main() { sx_vec2 v = sx_v2(1, 2); return (int)sx_length(v) - 2; }\n' \
	  | $(CXX) -std=c++11 -Wall -Wextra -pedantic -Werror $(DEFS) -Iinclude -x c++ -fsyntax-only -

# The README's code example is compiled and run, so it stays true.
README_EXAMPLE := $(OUT)/readme_example
readme-example: $(LIB_A)
	@mkdir -p $(OUT)
	@awk '/<!-- readme-example:begin -->/{f=1;next} /<!-- readme-example:end -->/{f=0} f' README.md \
	  | sed '/^```/d' > $(README_EXAMPLE).c
	@test -s $(README_EXAMPLE).c || { echo "sepax: README example block not found"; exit 1; }
	$(CC) $(CFLAGS_ALL) -o $(README_EXAMPLE) $(README_EXAMPLE).c $(LIB_A) $(LDLIBS_ALL)
	@./$(README_EXAMPLE) > $(README_EXAMPLE).out
	@echo "sepax: README example ran: $$(head -c 200 $(README_EXAMPLE).out)"

# The plain-C sample (samples/pyramid.c) is built with the strict flags and
# run on a small pyramid, so it stays working.
SAMPLE_PYRAMID := $(OUT)/samples/pyramid
$(SAMPLE_PYRAMID): samples/pyramid.c $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_ALL) -o $@ $< $(LIB_A) $(LDLIBS_ALL)
sample-pyramid: $(SAMPLE_PYRAMID)
	@./$(SAMPLE_PYRAMID) 5 1 > $(SAMPLE_PYRAMID).out
	@echo "sepax: samples/pyramid ran: $$(tail -n 1 $(SAMPLE_PYRAMID).out)"

test: lib check-headers readme-example sample-pyramid $(TEST_BINS)
	@failed=0; total=0; \
	for t in $(TEST_BINS); do \
	  total=$$((total + 1)); \
	  echo "== $$t"; \
	  if ! ./$$t; then failed=$$((failed + 1)); echo "FAILED: $$t"; fi; \
	done; \
	echo "sepax [$(SX_REAL)$(if $(filter 1,$(SAN)), san)$(if $(filter thread,$(SAN)), tsan)$(if $(filter 0,$(SIMD)), SIMD=0)]: $$((total - failed)) of $$total test programs passed"; \
	test $$failed -eq 0

# make stress: the hostile scenes (tests/test_hostile.c) with the long run of
# the busy scene at 100,000 steps instead of make test's 20,000
# (SX_HOSTILE_STEPS). Measured on the shared 2-core machine: the whole hostile
# program takes about 12 s of CPU with 100,000 steps in the float -O2 build and
# 43 s (62 s wall) under SAN=1, against 9 s under SAN=1 with make test's 20,000.
STRESS_STEPS ?= 100000
.PHONY: stress
stress: $(OUT)/tests/test_hostile
	SX_HOSTILE_STEPS=$(STRESS_STEPS) ./$(OUT)/tests/test_hostile

# make determinism: tests/test_determinism.c hashes the state after a scripted
# scene; here it is built with the library at -O0, -O2 and -O3 (same compiler,
# same flags otherwise: -ffp-contract=off, no -ffast-math) into
# build/determinism[-double][-nosimd]/O<n>/, and the three hashes must be
# equal. A second hash covers the narrowphase answers over random pairs;
# .ci/run also checks that SIMD=0 prints the same pair of hashes.
DET_LEVELS := O0 O2 O3
DET_OUT := build/determinism$(if $(filter double,$(SX_REAL)),-double)$(if $(filter 0,$(SIMD)),-nosimd)
DET_SRCS := $(SRCS) tests/test_determinism.c $(TEST_SUPPORT)
.PHONY: determinism
$(DET_OUT)/%/test_determinism: $(DET_SRCS) $(wildcard include/sepax/*.h src/*.h tests/support/*.h) | deps-test
	@mkdir -p $(dir $@)
	$(CC) -std=c99 -$* -ffp-contract=off $(WARNINGS) $(DEFS) -Iinclude -Itests/support $(CMOCKA_CFLAGS) \
	  -o $@ $(DET_SRCS) $(CMOCKA_LIBS) $(LDLIBS_ALL)
determinism: $(DET_LEVELS:%=$(DET_OUT)/%/test_determinism)
	@for o in $(DET_LEVELS); do \
	  ./$(DET_OUT)/$$o/test_determinism > $(DET_OUT)/$$o/out.txt 2>&1 || { cat $(DET_OUT)/$$o/out.txt; exit 1; }; \
	  h=$$(sed -n 's/^sepax determinism hash: //p' $(DET_OUT)/$$o/out.txt); \
	  h="$$h narrowphase $$(sed -n 's/^sepax narrowphase hash: //p' $(DET_OUT)/$$o/out.txt)"; \
	  echo "sepax determinism [$(SX_REAL)$(if $(filter 0,$(SIMD)), SIMD=0)] -$$o: $$h"; echo "$$h" >> $(DET_OUT)/hashes.tmp; \
	done; \
	n=$$(sort -u $(DET_OUT)/hashes.tmp | wc -l); rm -f $(DET_OUT)/hashes.tmp; \
	if [ "$$n" -ne 1 ]; then echo "sepax determinism: the hashes differ between optimisation levels"; exit 1; fi; \
	echo "sepax determinism [$(SX_REAL)$(if $(filter 0,$(SIMD)), SIMD=0)]: -O0, -O2 and -O3 agree"

# ---- benchmarks --------------------------------------------------------------
#
# bench/*.c is our code (strict flags, the float or double build of the
# library); bench/*.cpp are the peers, Box2D 2.4 and Chipmunk 7 (C++, relaxed
# flags). `make bench`
# prints the table and writes $(OUT)/bench/narrowphase.csv (build/bench for
# the float build); `make bench-smoke` runs every pair type a few times only.

BENCH_SRCS := $(sort $(wildcard bench/*.c))
BENCH_CXX_SRCS := $(sort $(wildcard bench/*.cpp))
BENCH_OBJS := $(BENCH_SRCS:bench/%.c=$(OUT)/obj/bench/%.o) \
              $(BENCH_CXX_SRCS:bench/%.cpp=$(OUT)/obj/bench/%.o)
BENCH_BIN := $(OUT)/bench/sepax_bench
BENCH_CFLAGS = $(filter-out -O2 -g,$(CFLAGS_ALL)) -O2 -DNDEBUG -Ibench -Itests/support

deps-bench:
	@sh scripts/deps.sh box2d chipmunk

$(OUT)/obj/bench/%.o: bench/%.c | $(OUT)/obj/bench deps-bench
	$(CC) $(BENCH_CFLAGS) -c $< -o $@

# The peer engines are C++ (Box2D 2.4): compiled with relaxed flags.
$(OUT)/obj/bench/%.o: bench/%.cpp | $(OUT)/obj/bench deps-bench
	$(CXX) -std=c++17 -O2 -DNDEBUG $(DEFS) -Iinclude -Ibench -MMD -MP -c $< -o $@

# The depth reference of the tests (tests/support/reference.c) is linked too.
BENCH_REF_OBJ := $(OUT)/obj/tests/support/reference.o
$(BENCH_BIN): $(BENCH_OBJS) $(BENCH_REF_OBJ) $(LIB_A) | $(OUT)/bench
	$(CXX) $(SANFLAGS) -o $@ $(BENCH_OBJS) $(BENCH_REF_OBJ) $(LIB_A) -lbox2d -lchipmunk $(LDLIBS_ALL)

bench: $(BENCH_BIN)
	./$(BENCH_BIN) --out $(OUT)/bench
	@{ printf '\n## Narrowphase (sx_collide against Box2D and Chipmunk)\n\n'; \
	  awk -F, -f scripts/narrowphase_table.awk $(OUT)/bench/narrowphase.csv; } >> $(OUT)/bench/REPORT.md

bench-smoke: $(BENCH_BIN)
	./$(BENCH_BIN) --smoke --out $(OUT)/bench-smoke

# The world scenes alone (bench/scenes.c: sepax, Box2D and Chipmunk worlds;
# scenes.csv, SVG plots and REPORT.md in $(OUT)/bench); `make bench` runs
# them after the narrowphase table.
.PHONY: bench-scenes
bench-scenes: $(BENCH_BIN)
	./$(BENCH_BIN) --scenes --out $(OUT)/bench

# ---- flecs module and demo ---------------------------------------------------
#
# flecs 4's amalgamated flecs.c/flecs.h come from the pinned crates.io package
# flecs_ecs_sys (fetched with cargo by scripts/fetch_flecs.sh into
# build/deps/flecs), or from FLECS_DIR=/path (the user's copy). flecs.c is
# compiled once, with relaxed flags, into its own object (per sanitizer
# setting: it does not depend on SX_REAL). ecs/ and the code that includes
# flecs.h get our strict flags; flecs.h comes in with -isystem, which silences
# the warnings inside flecs.h itself and nothing else.

FLECS_SRC_DIR := $(if $(FLECS_DIR),$(FLECS_DIR),build/deps/flecs)
FLECS_H := $(FLECS_SRC_DIR)/flecs.h
FLECS_C := $(FLECS_SRC_DIR)/flecs.c
FLECS_OBJ := $(if $(SANFLAGS),$(OUT)/obj/flecs/flecs.o,build/deps/flecs-obj/flecs.o)
ifneq ($(FLECS_DIR),)
  FLECS_OBJ := $(OUT)/obj/flecs-own/flecs.o
endif
FLECS_CFLAGS := -std=c99 -D_POSIX_C_SOURCE=200809L -O2 -fPIC -w $(SANFLAGS)
ECS_CFLAGS = $(CFLAGS_ALL) -isystem $(FLECS_SRC_DIR) -Iecs
ECS_LIBS := -lpthread -lm
ECS_OBJ := $(OUT)/obj/ecs/sepax_flecs.o
TEST_ECS := $(OUT)/tests/test_ecs
DEMO_BIN := $(OUT)/samples/demo

.PHONY: demo flecs

$(FLECS_H):
	@sh scripts/fetch_flecs.sh $(FLECS_SRC_DIR)
$(FLECS_C): $(FLECS_H)
flecs: $(FLECS_OBJ)

$(FLECS_OBJ): $(FLECS_C)
	@mkdir -p $(dir $@)
	$(CC) $(FLECS_CFLAGS) -c $(FLECS_C) -o $@

$(ECS_OBJ): ecs/sepax_flecs.c ecs/sepax_flecs.h $(FLECS_H)
	@mkdir -p $(dir $@)
	$(CC) $(ECS_CFLAGS) -c $< -o $@

$(OUT)/obj/tests/test_ecs.o: tests/test_ecs.c $(FLECS_H) | $(OUT)/obj/tests deps-test
	$(CC) $(ECS_CFLAGS) $(CMOCKA_CFLAGS) -Itests/support -c $< -o $@

$(TEST_ECS): $(OUT)/obj/tests/test_ecs.o $(ECS_OBJ) $(FLECS_OBJ) $(TEST_SUPPORT_OBJS) $(LIB_A) | $(OUT)/tests
	$(CC) $(SANFLAGS) -o $@ $< $(ECS_OBJ) $(FLECS_OBJ) $(TEST_SUPPORT_OBJS) $(LIB_A) $(CMOCKA_LIBS) $(ECS_LIBS)

$(OUT)/obj/samples/demo.o: samples/demo.c ecs/sepax_flecs.h $(FLECS_H)
	@mkdir -p $(dir $@)
	$(CC) $(ECS_CFLAGS) -c $< -o $@

$(DEMO_BIN): $(OUT)/obj/samples/demo.o $(ECS_OBJ) $(FLECS_OBJ) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(SANFLAGS) -o $@ $< $(ECS_OBJ) $(FLECS_OBJ) $(LIB_A) $(ECS_LIBS)

demo: $(DEMO_BIN)
	@mkdir -p build/demo
	./$(DEMO_BIN) build/demo/final.svg

# make bench also measures the module's overhead over the plain world
# (bench/ecs/overhead.c: the same 10,000-body scene stepped both ways);
# make bench-ecs runs it alone, bench-smoke runs it for a few steps.
BENCH_ECS_BIN := $(OUT)/bench/sepax_bench_ecs
.PHONY: bench-ecs bench-ecs-smoke
$(OUT)/obj/bench/ecs/overhead.o: bench/ecs/overhead.c ecs/sepax_flecs.h $(FLECS_H)
	@mkdir -p $(dir $@)
	$(CC) $(filter-out -O2 -g,$(ECS_CFLAGS)) -O2 -DNDEBUG -c $< -o $@

$(BENCH_ECS_BIN): $(OUT)/obj/bench/ecs/overhead.o $(ECS_OBJ) $(FLECS_OBJ) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(SANFLAGS) -o $@ $< $(ECS_OBJ) $(FLECS_OBJ) $(LIB_A) $(ECS_LIBS)

bench-ecs: $(BENCH_ECS_BIN)
	./$(BENCH_ECS_BIN) --out $(OUT)/bench
bench-ecs-smoke: $(BENCH_ECS_BIN)
	@mkdir -p $(OUT)/bench-smoke
	./$(BENCH_ECS_BIN) --steps 3 --out $(OUT)/bench-smoke
bench: bench-ecs
bench-smoke: bench-ecs-smoke

-include $(ECS_OBJ:.o=.d) $(OUT)/obj/samples/demo.d $(OUT)/obj/bench/ecs/overhead.d

# ---- fuzzing -----------------------------------------------------------------

# make fuzz [FUZZ_SECONDS=60] [FUZZ_RUNS=N] [FUZZ_HARNESSES="world ..."]
# [SX_REAL=double]: builds every fuzz/fuzz_<h>.c
# with clang's libFuzzer under ASan + UBSan (the library too, so its branches
# guide the fuzzer) and runs each for FUZZ_SECONDS on a copy of
# fuzz/corpus/<h>/. A broken invariant aborts and leaves the input in
# build/fuzz[-double]/crash-<h>-* (FUZZ_FLAGS="-fork=1 -ignore_crashes=1"
# keeps fuzzing past failures; FUZZ_RUNS=10000000 stops each harness after
# that many executions, or at FUZZ_SECONDS if that comes first). make
# fuzz-merge adds the inputs a run found that bring new coverage to
# fuzz/corpus/<h>/ (keep that small).
.PHONY: fuzz fuzz-build fuzz-merge deps-fuzz
FUZZ_SECONDS ?= 60
FUZZ_FLAGS ?=
FUZZ_RUNS ?=
FUZZ_CC ?= clang
FUZZ_HARNESSES := $(sort $(patsubst fuzz/fuzz_%.c,%,$(wildcard fuzz/fuzz_*.c)))
FUZZ_OUT := build/fuzz$(if $(filter double,$(SX_REAL)),-double)
FUZZ_CFLAGS := -std=c99 -O1 -g -ffp-contract=off $(WARNINGS) $(DEFS) -Iinclude -MMD -MP \
               -fno-omit-frame-pointer -fno-sanitize-recover=all
FUZZ_LIB_OBJS := $(SRCS:src/%.c=$(FUZZ_OUT)/obj/%.o)
FUZZ_BINS := $(FUZZ_HARNESSES:%=$(FUZZ_OUT)/fuzz_%)

deps-fuzz:
	@sh scripts/deps.sh fuzz

$(FUZZ_OUT)/obj/%.o: src/%.c | deps-fuzz
	@mkdir -p $(dir $@)
	$(FUZZ_CC) $(FUZZ_CFLAGS) -fsanitize=fuzzer-no-link,address,undefined -c $< -o $@

$(FUZZ_OUT)/fuzz_%: fuzz/fuzz_%.c $(FUZZ_LIB_OBJS) | deps-fuzz
	$(FUZZ_CC) $(FUZZ_CFLAGS) -fsanitize=fuzzer,address,undefined -o $@ $< $(FUZZ_LIB_OBJS) -lm

fuzz-build: $(FUZZ_BINS)

fuzz: $(FUZZ_BINS)
	@failed=0; \
	for h in $(FUZZ_HARNESSES); do \
	  work=$(FUZZ_OUT)/corpus/$$h; rm -rf $$work; mkdir -p $$work; \
	  if [ -d fuzz/corpus/$$h ]; then cp fuzz/corpus/$$h/* $$work/ 2>/dev/null; fi; \
	  log=$(FUZZ_OUT)/$$h.log; \
	  if ./$(FUZZ_OUT)/fuzz_$$h -max_total_time=$(FUZZ_SECONDS) -max_len=1024 -timeout=10 \
	       -print_final_stats=1 -artifact_prefix=$(FUZZ_OUT)/crash-$$h- \
	       $(if $(FUZZ_RUNS),-runs=$(FUZZ_RUNS)) $(FUZZ_FLAGS) $$work \
	       > $$log 2>&1; \
	  then verdict=clean; else failed=$$((failed + 1)); \
	    verdict="FAILED: $$(grep -m1 -E 'invariant broken|ERROR:|runtime error' $$log | cut -c1-160) (see $$log)"; fi; \
	  execs=$$(sed -n 's/^stat::number_of_executed_units: *//p' $$log | tail -n 1); \
	  rate=$$(sed -n 's/^stat::average_exec_per_sec: *//p' $$log | tail -n 1); \
	  last=$$(grep -E '^#[0-9]+:.*crash: ' $$log | tail -n 1); \
	  if [ -z "$$execs" ] && [ -n "$$last" ]; then \
	    execs=$$(echo "$$last" | sed 's/^#\([0-9]*\).*/\1/'); \
	    rate=$$(echo "$$last" | sed 's/.*exec\/s \([0-9]*\).*/\1/'); \
	    crashes=$$(echo "$$last" | sed 's/.*crash: [0-9]*\/[0-9]*\/\([0-9]*\).*/\1/'); \
	    if [ "$${crashes:-0}" -gt 0 ]; then failed=$$((failed + 1)); \
	      verdict="FAILED: $$crashes failing inputs in $(FUZZ_OUT)/crash-$$h-*"; fi; \
	  fi; \
	  echo "sepax fuzz $$h: $${execs:-?} executions ($${rate:-?}/s, limit $(FUZZ_SECONDS) s): $$verdict"; \
	done; \
	test $$failed -eq 0

fuzz-merge: $(FUZZ_BINS)
	@for h in $(FUZZ_HARNESSES); do \
	  mkdir -p fuzz/corpus/$$h; \
	  ./$(FUZZ_OUT)/fuzz_$$h -merge=1 -max_len=1024 fuzz/corpus/$$h $(FUZZ_OUT)/corpus/$$h; \
	done

-include $(FUZZ_LIB_OBJS:.o=.d) $(FUZZ_BINS:=.d)

# ---- install -----------------------------------------------------------------

install: lib
	install -d $(DESTDIR)$(PREFIX)/include/sepax $(DESTDIR)$(PREFIX)/lib/pkgconfig
	install -m 644 include/sepax/*.h $(DESTDIR)$(PREFIX)/include/sepax/
	install -m 644 $(LIB_A) $(DESTDIR)$(PREFIX)/lib/
	install -m 755 $(LIB_SO) $(DESTDIR)$(PREFIX)/lib/
	install -d $(DESTDIR)$(PREFIX)/share/sepax/ecs
	install -m 644 ecs/sepax_flecs.h ecs/sepax_flecs.c $(DESTDIR)$(PREFIX)/share/sepax/ecs/
	sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@CFLAGS@|$(DEFS)|g' \
	    -e 's|@VERSION@|$(shell sed -n 's/^#define SX_VERSION_\(MAJOR\|MINOR\|PATCH\) \([0-9]*\)/\2/p' include/sepax/base.h | paste -sd.)|g' \
	    scripts/sepax.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/sepax.pc

# ---- housekeeping --------------------------------------------------------------

FORMAT_FILES = $(wildcard include/sepax/*.h src/*.c src/*.h tests/*.c tests/*.h tests/support/*.c \
                 tests/support/*.h samples/*.c bench/*.c bench/*.h ecs/*.c ecs/*.h)
# clang-format, or Debian's versioned name when only that is installed
CLANG_FORMAT ?= $(or $(shell command -v clang-format 2>/dev/null),$(shell command -v clang-format-14 2>/dev/null),clang-format)
format:
	$(CLANG_FORMAT) -i $(FORMAT_FILES)
format-check:
	$(CLANG_FORMAT) --dry-run --Werror $(FORMAT_FILES)

clean:
	rm -rf build

-include $(OBJS:.o=.d) $(TEST_SRCS:tests/%.c=$(OUT)/obj/tests/%.d) \
         $(TEST_SUPPORT_OBJS:.o=.d) $(BENCH_OBJS:.o=.d)
