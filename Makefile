# sepax — build, test, install.
#
#   make                      build/libsepax.a and build/libsepax.so
#   make test                 build and run every cmocka test (float build)
#   make test SX_REAL=double  the same with sx_real = double
#   make test SAN=1           the tests under AddressSanitizer + UBSan
#   make test SAN=thread      the tests under ThreadSanitizer (test_threads
#                             runs worlds on two threads)
#   make test SIMD=0          the float build without its SSE loops (portable C)
#   make test SIMD=avx2       the solver's lanes eight wide with AVX2 (CPUs with avx2)
#   make stress               the hostile scenes with the 100,000-step long run
#   make determinism          the determinism hash at -O0, -O2 and -O3 must agree
#   make mutate               the mutation check: the tests must catch each bug of a list
#   make bench                benchmarks (installs the peers it compares with)
#   make install PREFIX=/usr/local   (make uninstall PREFIX=... removes it)
#   make clean
#   make help                 every target, one line each
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
else ifeq ($(SIMD),avx2)
  # The solver's lanes eight wide in the float build (src/simd.h). -mavx2
  # without -mfma: no fused multiply-add, each lane computes what SSE2 does.
  # Built only where the CPU runs it: no fallback that would hide the choice.
  ifeq ($(shell grep -qw avx2 /proc/cpuinfo 2>/dev/null && echo yes),)
    $(error SIMD=avx2: this CPU has no AVX2 (no avx2 flag in /proc/cpuinfo); build with SIMD=1)
  endif
  VARIANT := $(if $(VARIANT),$(VARIANT)-avx2,avx2)
  DEFS += -mavx2
else ifneq ($(SIMD),1)
  $(error SIMD must be 1, 0 or avx2)
endif
# The SIMD variant as the summaries print it.
SIMD_TAG := $(if $(filter 0,$(SIMD)), SIMD=0)$(if $(filter avx2,$(SIMD)), SIMD=avx2)
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

# Quiet build lines ("  CC     src/body.c") by default; V=1 prints every
# command in full.
V ?= 0
ifeq ($(V),1)
  Q :=
  msg =
else
  Q := @
  msg = @printf '  %-6s %s\n' '$(1)' '$(2)'
endif

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
# The shared library is versioned: libsepax.so.MAJOR.MINOR.PATCH, with the
# SONAME libsepax.so.MAJOR (what a program records and the loader looks
# for) and the links libsepax.so.MAJOR and libsepax.so (what -lsepax finds).
SX_VERSION_PART = $(shell sed -n 's/^\#define SX_VERSION_$(1) \([0-9]*\)/\1/p' include/sepax/base.h)
VERSION_MAJOR := $(call SX_VERSION_PART,MAJOR)
VERSION := $(VERSION_MAJOR).$(call SX_VERSION_PART,MINOR).$(call SX_VERSION_PART,PATCH)
SONAME := libsepax.so.$(VERSION_MAJOR)
LIB_SO := $(OUT)/libsepax.so
LIB_SO_REAL := $(OUT)/libsepax.so.$(VERSION)

# tests/test_*.c use the public API only; the white-box tests of
# tests/internal/ may include src/ (make check-layers allows nothing else to)
# and link the static library, which keeps the internal symbols.
TEST_SRCS := $(sort $(wildcard tests/test_*.c)) $(sort $(wildcard tests/internal/test_*.c))
TEST_SUPPORT := $(sort $(wildcard tests/support/*.c))
TEST_SUPPORT_OBJS := $(TEST_SUPPORT:tests/support/%.c=$(OUT)/obj/tests/support/%.o)
TEST_BINS := $(patsubst %.c,$(OUT)/tests/%,$(notdir $(TEST_SRCS)))
CMOCKA_CFLAGS = $(shell pkg-config --cflags cmocka 2>/dev/null)
CMOCKA_LIBS = $(shell pkg-config --libs cmocka 2>/dev/null || echo -lcmocka)

.PHONY: all lib test check-exports check-layers file-map check-headers readme-example doc-examples sample-pyramid deps-test deps-bench \
        install uninstall clean bench bench-smoke format format-check help
.DEFAULT_GOAL := all
.SECONDARY:

all: lib
lib: $(LIB_A) $(LIB_SO_REAL) $(LIB_SO)

# The library's own objects hide every symbol that the public headers do not
# mark SX_API (check-exports holds libsepax.so to that list). They depend on
# the Makefile so that a change of flags rebuilds them.
$(OUT)/obj/src/%.o: src/%.c Makefile | $(OUT)/obj/src
	$(call msg,CC,$<)
	$(Q)$(CC) $(CFLAGS_ALL) -fvisibility=hidden -c $< -o $@

$(LIB_A): $(OBJS)
	$(Q)rm -f $@
	$(call msg,AR,$@)
	$(Q)ar rcs $@ $^

$(LIB_SO_REAL): $(OBJS)
	$(call msg,LD,$@)
	$(Q)$(CC) -shared -Wl,-soname,$(SONAME) $(SANFLAGS) -o $@ $^ $(LDLIBS_ALL)
	$(Q)ln -sf $(notdir $(LIB_SO_REAL)) $(OUT)/$(SONAME)
	$(Q)ln -sf $(SONAME) $(LIB_SO)

$(LIB_SO): $(LIB_SO_REAL)
	$(call msg,LN,$@)
	$(Q)ln -sf $(notdir $(LIB_SO_REAL)) $(OUT)/$(SONAME)
	$(Q)ln -sf $(SONAME) $@

$(OUT)/obj/src $(OUT)/obj/tests $(OUT)/obj/tests/support $(OUT)/tests $(OUT)/obj/bench $(OUT)/bench:
	$(Q)mkdir -p $@

# ---- tests ------------------------------------------------------------------

deps-test:
	@sh scripts/deps.sh cmocka

$(OUT)/obj/tests/support/%.o: tests/support/%.c | $(OUT)/obj/tests/support deps-test
	$(call msg,CC,$<)
	$(Q)$(CC) $(CFLAGS_ALL) $(CMOCKA_CFLAGS) -Itests/support -c $< -o $@

$(OUT)/obj/tests/%.o: tests/%.c | $(OUT)/obj/tests deps-test
	$(call msg,CC,$<)
	$(Q)$(CC) $(CFLAGS_ALL) $(CMOCKA_CFLAGS) -Itests/support -c $< -o $@

$(OUT)/obj/tests/%.o: tests/internal/%.c | $(OUT)/obj/tests deps-test
	$(call msg,CC,$<)
	$(Q)$(CC) $(CFLAGS_ALL) $(CMOCKA_CFLAGS) -Itests/support -c $< -o $@

$(OUT)/tests/%: $(OUT)/obj/tests/%.o $(TEST_SUPPORT_OBJS) $(LIB_A) | $(OUT)/tests
	$(call msg,LD,$@)
	$(Q)$(CC) $(SANFLAGS) -o $@ $< $(TEST_SUPPORT_OBJS) $(LIB_A) $(CMOCKA_LIBS) $(LDLIBS_ALL) $(TEST_LDLIBS)

# tests/test_threads.c runs worlds on POSIX threads.
$(OUT)/obj/tests/test_threads.o: CFLAGS += -pthread
$(OUT)/tests/test_threads: TEST_LDLIBS := -pthread

# libsepax.so exports exactly the functions declared in include/sepax/*.h,
# each marked SX_API (the list is read from the headers, not kept by hand).
check-exports: $(LIB_SO_REAL)
	@sh scripts/check_exports.sh $(LIB_SO_REAL) include/sepax/*.h

# The include lines prove the layering base <- shape <- collide <- world <-
# ecs, and only tests/internal/ includes src/ (scripts/check_layers.sh holds
# the table of layers).
check-layers:
	@sh scripts/check_layers.sh

# The map of src/: each file's layer, lines and concept, and the longest
# functions (N=25 lists more).
file-map:
	@sh scripts/file_map.sh

# Public headers must compile as C++ too.
# With include/sepax itself on the include path, no sepax header may take the
# place of a C library header (<math.h> here).
check-headers:
	@echo "sepax: compiling the public headers as C++"
	@printf '#include <sepax/sepax.h>\nint main() { sx_vec2 v = sx_v2(1, 2); return (int)sx_length(v) - 2; }\n' \
	  | $(CXX) -std=c++11 -Wall -Wextra -pedantic -Werror $(DEFS) -Iinclude -x c++ -fsyntax-only -
	@printf '#include <math.h>\n#include "sepax.h"\nint main(void) { return (int)(sqrt(4.0) + sx_length(sx_v2(0, 0))) - 2; }\n' \
	  | $(CC) -std=c99 -Wall -Wextra -pedantic -Werror $(DEFS) -Iinclude/sepax -x c -fsyntax-only -

# Every C code block of README.md and the C and C++ blocks of the usage
# comment atop ecs/sepax_flecs.h are compiled with the strict flags and run,
# so the documentation stays true (blocks that include sepax_flecs.h are
# linked with the flecs module and flecs). Their shell blocks (install,
# linking, the flecs build lines) are run as written by .ci/run.
# They are compiled with the warnings a user's own build would turn on
# (-Wall -Wextra -pedantic -Werror), not with the library's stricter set.
DOC_OUT := $(OUT)/doc-examples
DOC_CFLAGS = -std=c99 $(OPT) -Wall -Wextra -pedantic -Werror $(SANFLAGS) $(DEFS) -Iinclude
DOC_CXXFLAGS = -std=c++17 $(OPT) -Wall -Wextra -pedantic -Werror $(SANFLAGS) $(DEFS) -Iinclude -Iecs \
               -isystem $(FLECS_SRC_DIR)
doc-examples: $(LIB_A)
	@rm -rf $(DOC_OUT)
	@set -e; \
	c=$$(sh scripts/code_blocks.sh README.md c $(DOC_OUT) c; sh scripts/code_blocks.sh ecs/sepax_flecs.h c $(DOC_OUT) c); \
	cxx=$$(sh scripts/code_blocks.sh ecs/sepax_flecs.h cpp $(DOC_OUT) cpp); \
	[ $$(echo $$c | wc -w) -ge 4 ] && [ -n "$$cxx" ] || { echo "sepax: doc-examples: code blocks not found"; exit 1; }; \
	for f in $$c $$cxx; do \
	  bin=$${f%.*}; $(if $(filter 1,$(V)),set -x;) \
	  case $$f in \
	    *.cpp) echo "  CXX  $$f"; $(CXX) $(DOC_CXXFLAGS) -o $$bin $$f $(ECS_OBJ) $(FLECS_OBJ) $(LIB_A) $(ECS_LIBS) ;; \
	    *) if grep -q 'sepax_flecs.h' $$f; then echo "  CC   $$f (flecs)"; \
	         $(CC) $(DOC_CFLAGS) -Iecs -isystem $(FLECS_SRC_DIR) -o $$bin $$f $(ECS_OBJ) $(FLECS_OBJ) $(LIB_A) $(ECS_LIBS); \
	       else echo "  CC   $$f"; $(CC) $(DOC_CFLAGS) -o $$bin $$f $(LIB_A) $(LDLIBS_ALL); fi ;; \
	  esac; \
	  ./$$bin > $$bin.out 2>&1 || { cat $$bin.out; echo "sepax: $$f (from the documentation) failed"; exit 1; }; \
	  echo "sepax: $$f ran: $$(head -n 1 $$bin.out)"; \
	done
readme-example: doc-examples

# The plain-C sample (samples/pyramid.c) is built with the strict flags and
# run on a small pyramid, so it stays working.
SAMPLE_PYRAMID := $(OUT)/samples/pyramid
$(SAMPLE_PYRAMID): samples/pyramid.c samples/task_pool.h $(LIB_A)
	@mkdir -p $(dir $@)
	$(call msg,CC,$<)
	$(Q)$(CC) $(CFLAGS_ALL) -pthread -o $@ $< $(LIB_A) $(LDLIBS_ALL) -pthread
sample-pyramid: $(SAMPLE_PYRAMID)
	@./$(SAMPLE_PYRAMID) 5 1 > $(SAMPLE_PYRAMID).out
	@echo "sepax: samples/pyramid ran: $$(tail -n 1 $(SAMPLE_PYRAMID).out)"
	@./$(SAMPLE_PYRAMID) 20 1 nosleep 2 > $(SAMPLE_PYRAMID)-2.out
	@echo "sepax: samples/pyramid ran on 2 workers: $$(tail -n 1 $(SAMPLE_PYRAMID)-2.out)"

test: lib check-exports check-layers check-headers doc-examples sample-pyramid $(TEST_BINS)
	@failed=0; total=0; \
	for t in $(TEST_BINS); do \
	  total=$$((total + 1)); \
	  echo "== $$t"; \
	  if ! ./$$t; then failed=$$((failed + 1)); echo "FAILED: $$t"; fi; \
	done; \
	echo "sepax [$(SX_REAL)$(if $(filter 1,$(SAN)), san)$(if $(filter thread,$(SAN)), tsan)$(SIMD_TAG)]: $$((total - failed)) of $$total test programs passed"; \
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
# .ci/run also checks that SIMD=0 prints the same pair of hashes. Both must
# also equal the values pinned per build in tests/test_determinism.c
# (det_pins): a failure prints the line to pin when a change is intended.
DET_LEVELS := O0 O2 O3
DET_OUT := build/determinism$(if $(filter double,$(SX_REAL)),-double)$(if $(filter 0,$(SIMD)),-nosimd)$(if $(filter avx2,$(SIMD)),-avx2)
DET_SRCS := $(SRCS) tests/test_determinism.c $(TEST_SUPPORT)
.PHONY: determinism
$(DET_OUT)/%/test_determinism: $(DET_SRCS) $(wildcard include/sepax/*.h src/*.h tests/support/*.h) | deps-test
	@mkdir -p $(dir $@)
	$(call msg,CC,$@)
	$(Q)$(CC) -std=c99 -$* -ffp-contract=off $(WARNINGS) $(DEFS) -Iinclude -Itests/support $(CMOCKA_CFLAGS) \
	  -o $@ $(DET_SRCS) $(CMOCKA_LIBS) $(LDLIBS_ALL)
determinism: $(DET_LEVELS:%=$(DET_OUT)/%/test_determinism)
	@for o in $(DET_LEVELS); do \
	  ./$(DET_OUT)/$$o/test_determinism > $(DET_OUT)/$$o/out.txt 2>&1 || { cat $(DET_OUT)/$$o/out.txt; exit 1; }; \
	  h=$$(sed -n 's/^sepax determinism hash: //p' $(DET_OUT)/$$o/out.txt); \
	  h="$$h narrowphase $$(sed -n 's/^sepax narrowphase hash: //p' $(DET_OUT)/$$o/out.txt)"; \
	  echo "sepax determinism [$(SX_REAL)$(SIMD_TAG)] -$$o: $$h"; echo "$$h" >> $(DET_OUT)/hashes.tmp; \
	done; \
	n=$$(sort -u $(DET_OUT)/hashes.tmp | wc -l); rm -f $(DET_OUT)/hashes.tmp; \
	if [ "$$n" -ne 1 ]; then echo "sepax determinism: the hashes differ between optimisation levels"; exit 1; fi; \
	echo "sepax determinism [$(SX_REAL)$(SIMD_TAG)]: -O0, -O2 and -O3 agree"

# make mutate [MUTATIONS=name,name]: the mutation check (scripts/mutate.py):
# each small deliberate bug of tests/mutations.txt (solver, narrowphase,
# broadphase, sleeping) is applied alone to a copy of the tree in
# build/mutate/tree, the test programs run until one fails, and the bugs no
# test caught are reported (exit status 1 if any, or if an anchor no longer
# matches the code). The working tree is never written. Needs python3; about
# 6 minutes on the shared 2-core machine, so not part of make test or CI.
.PHONY: mutate
mutate:
	python3 scripts/mutate.py $(if $(MUTATIONS),--only $(MUTATIONS))

# ---- benchmarks --------------------------------------------------------------
#
# bench/*.c is our code (strict flags, the float or double build of the
# library); bench/*.cpp are the Debian peers, Box2D 2.4 and Chipmunk 7 (C++,
# relaxed flags); bench/box2d3/ is the glue to Box2D v3 (below). `make bench`
# prints the table and writes $(OUT)/bench/narrowphase.csv (build/bench for
# the float build); `make bench-smoke` runs every pair type a few times only.

BENCH_SRCS := $(sort $(wildcard bench/*.c))
BENCH_CXX_SRCS := $(sort $(wildcard bench/*.cpp))
BENCH_OBJS := $(BENCH_SRCS:bench/%.c=$(OUT)/obj/bench/%.o) \
              $(BENCH_CXX_SRCS:bench/%.cpp=$(OUT)/obj/bench/%.o)
BENCH_BIN := $(OUT)/bench/sepax_bench
BENCH_CFLAGS = $(filter-out -O2 -g,$(CFLAGS_ALL)) -O2 -DNDEBUG -Ibench -Itests/support

deps-bench: $(BOX2D3_STAMP)
	@sh scripts/deps.sh box2d chipmunk

$(OUT)/obj/bench/%.o: bench/%.c | $(OUT)/obj/bench deps-bench
	$(call msg,CC,$<)
	$(Q)$(CC) $(BENCH_CFLAGS) -c $< -o $@

# The peer engines are C++ (Box2D 2.4): compiled with relaxed flags.
$(OUT)/obj/bench/%.o: bench/%.cpp | $(OUT)/obj/bench deps-bench
	$(call msg,CXX,$<)
	$(Q)$(CXX) -std=c++17 -O2 -DNDEBUG $(DEFS) -Iinclude -Ibench -MMD -MP -c $< -o $@

# Box2D v3, the headline peer: its C source comes from the pinned crates.io
# package boxdd-sys (scripts/fetch_box2d3.sh, with cargo) into
# build/deps/box2d3/box2d, or from BOX2D3_DIR=/path. It is built three ways
# (its default SSE2 path, AVX2, and the portable scalar path), each with its
# own flags (-std=c17 -O2 -DNDEBUG, warnings off: foreign code) into an
# archive of its own; none of its flags reach sepax's code. Our glue in
# bench/box2d3/ is compiled once per build and linked with that archive into
# one relocatable object whose only global symbols end in box2d3_<build>, so
# the three builds share one bench program. The AVX2 build compiles on any
# x86-64 CPU and runs only where the CPU has AVX2 (checked at run time).
BOX2D3_SRC := $(if $(BOX2D3_DIR),$(BOX2D3_DIR),build/deps/box2d3/box2d)
BOX2D3_STAMP := $(BOX2D3_SRC)/include/box2d/box2d.h
BOX2D3_LIB_DIR := build/deps/box2d3-lib$(if $(BOX2D3_DIR),-own)
BOX2D3_BUILDS := sse2 avx2 scalar
BOX2D3_FLAGS_sse2 :=
BOX2D3_FLAGS_avx2 := -DBOX2D_AVX2 -mavx2
BOX2D3_FLAGS_scalar := -DBOX2D_DISABLE_SIMD
BOX2D3_CFLAGS := -std=c17 -O2 -DNDEBUG -fPIC -w
BOX2D3_GLUE_SRCS := $(sort $(wildcard bench/box2d3/*.c))
BOX2D3_OBJS := $(BOX2D3_BUILDS:%=$(OUT)/obj/bench/box2d3_%.o)

$(BOX2D3_STAMP):
	@sh scripts/fetch_box2d3.sh $(BOX2D3_SRC)

$(BOX2D3_LIB_DIR)/%/libbox2d3.a: $(BOX2D3_STAMP)
	@mkdir -p $(dir $@)
	@echo "sepax: building Box2D v3 ($*) into $(dir $@)"
	@set -e; for f in $(BOX2D3_SRC)/src/*.c; do \
	  $(if $(filter 1,$(V)),set -x;) $(CC) $(BOX2D3_CFLAGS) $(BOX2D3_FLAGS_$*) -I$(BOX2D3_SRC)/include -c $$f \
	    -o $(dir $@)$$(basename $$f .c).o; \
	done; rm -f $@; ar rcs $@ $(dir $@)*.o

$(OUT)/obj/bench/box2d3_%.o: $(BOX2D3_GLUE_SRCS) bench/box2d3/b3_export.h bench/scenes.h bench/pairs.h \
                             $(BOX2D3_LIB_DIR)/%/libbox2d3.a | $(OUT)/obj/bench
	@mkdir -p $(OUT)/obj/bench/box2d3-$*
	@set -e; for f in $(BOX2D3_GLUE_SRCS); do \
	  echo "  CC     [box2d3 $*] $$f"; \
	  $(if $(filter 1,$(V)),set -x;) $(CC) -std=c17 -O2 -DNDEBUG -fPIC $(WARNINGS) $(BOX2D3_FLAGS_$*) -DB3_SUFFIX=$* \
	    -isystem $(BOX2D3_SRC)/include -Ibench -Itests/support -c $$f \
	    -o $(OUT)/obj/bench/box2d3-$*/$$(basename $$f .c).o; \
	done
	$(call msg,LD,$@)
	$(Q)ld -r -o $@.all.o $(OUT)/obj/bench/box2d3-$*/*.o --whole-archive $(BOX2D3_LIB_DIR)/$*/libbox2d3.a
	$(Q)objcopy --wildcard --keep-global-symbol='*box2d3_$*' $@.all.o $@
	@rm -f $@.all.o

# The depth reference of the tests (tests/support/reference.c) is linked too.
BENCH_REF_OBJ := $(OUT)/obj/tests/support/reference.o
$(BENCH_BIN): $(BENCH_OBJS) $(BOX2D3_OBJS) $(BENCH_REF_OBJ) $(LIB_A) | $(OUT)/bench
	$(call msg,LD,$@)
	$(Q)$(CXX) $(SANFLAGS) -o $@ $(BENCH_OBJS) $(BOX2D3_OBJS) $(BENCH_REF_OBJ) $(LIB_A) -lbox2d -lchipmunk $(LDLIBS_ALL)

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
	$(call msg,CC,$(FLECS_C))
	$(Q)$(CC) $(FLECS_CFLAGS) -c $(FLECS_C) -o $@

# (the examples of the documentation link the module: see doc-examples)
doc-examples: $(ECS_OBJ) $(FLECS_OBJ)

$(ECS_OBJ): ecs/sepax_flecs.c ecs/sepax_flecs.h $(FLECS_H)
	@mkdir -p $(dir $@)
	$(call msg,CC,$<)
	$(Q)$(CC) $(ECS_CFLAGS) -c $< -o $@

$(OUT)/obj/tests/test_ecs.o: tests/test_ecs.c $(FLECS_H) | $(OUT)/obj/tests deps-test
	$(call msg,CC,$<)
	$(Q)$(CC) $(ECS_CFLAGS) $(CMOCKA_CFLAGS) -Itests/support -c $< -o $@

$(TEST_ECS): $(OUT)/obj/tests/test_ecs.o $(ECS_OBJ) $(FLECS_OBJ) $(TEST_SUPPORT_OBJS) $(LIB_A) | $(OUT)/tests
	$(call msg,LD,$@)
	$(Q)$(CC) $(SANFLAGS) -o $@ $< $(ECS_OBJ) $(FLECS_OBJ) $(TEST_SUPPORT_OBJS) $(LIB_A) $(CMOCKA_LIBS) $(ECS_LIBS)

$(OUT)/obj/samples/demo.o: samples/demo.c ecs/sepax_flecs.h $(FLECS_H)
	@mkdir -p $(dir $@)
	$(call msg,CC,$<)
	$(Q)$(CC) $(ECS_CFLAGS) -c $< -o $@

$(DEMO_BIN): $(OUT)/obj/samples/demo.o $(ECS_OBJ) $(FLECS_OBJ) $(LIB_A)
	@mkdir -p $(dir $@)
	$(call msg,LD,$@)
	$(Q)$(CC) $(SANFLAGS) -o $@ $< $(ECS_OBJ) $(FLECS_OBJ) $(LIB_A) $(ECS_LIBS)

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
	$(call msg,CC,$<)
	$(Q)$(CC) $(filter-out -O2 -g,$(ECS_CFLAGS)) -O2 -DNDEBUG -c $< -o $@

$(BENCH_ECS_BIN): $(OUT)/obj/bench/ecs/overhead.o $(ECS_OBJ) $(FLECS_OBJ) $(LIB_A)
	@mkdir -p $(dir $@)
	$(call msg,LD,$@)
	$(Q)$(CC) $(SANFLAGS) -o $@ $< $(ECS_OBJ) $(FLECS_OBJ) $(LIB_A) $(ECS_LIBS)

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
	$(call msg,CC,$<)
	$(Q)$(FUZZ_CC) $(FUZZ_CFLAGS) -fsanitize=fuzzer-no-link,address,undefined -c $< -o $@

$(FUZZ_OUT)/fuzz_%: fuzz/fuzz_%.c $(FUZZ_LIB_OBJS) | deps-fuzz
	$(call msg,LD,$@)
	$(Q)$(FUZZ_CC) $(FUZZ_CFLAGS) -fsanitize=fuzzer,address,undefined -o $@ $< $(FUZZ_LIB_OBJS) -lm

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

INSTALL_FILES = include/sepax/*.h lib/libsepax.a lib/libsepax.so lib/$(SONAME) \
                lib/libsepax.so.$(VERSION) lib/pkgconfig/sepax.pc share/sepax/ecs/sepax_flecs.h \
                share/sepax/ecs/sepax_flecs.c
install: lib
	install -d $(DESTDIR)$(PREFIX)/include/sepax $(DESTDIR)$(PREFIX)/lib/pkgconfig
	install -m 644 include/sepax/*.h $(DESTDIR)$(PREFIX)/include/sepax/
	rm -f $(DESTDIR)$(PREFIX)/include/sepax/math.h  # the former name of vecmath.h, which shadowed <math.h>
	install -m 644 $(LIB_A) $(DESTDIR)$(PREFIX)/lib/
	install -m 755 $(LIB_SO_REAL) $(DESTDIR)$(PREFIX)/lib/
	ln -sf libsepax.so.$(VERSION) $(DESTDIR)$(PREFIX)/lib/$(SONAME)
	ln -sf $(SONAME) $(DESTDIR)$(PREFIX)/lib/libsepax.so
	install -d $(DESTDIR)$(PREFIX)/share/sepax/ecs
	install -m 644 ecs/sepax_flecs.h ecs/sepax_flecs.c $(DESTDIR)$(PREFIX)/share/sepax/ecs/
	sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@CFLAGS@|$(DEFS)|g' -e 's|@VERSION@|$(VERSION)|g' \
	    scripts/sepax.pc.in > $(DESTDIR)$(PREFIX)/lib/pkgconfig/sepax.pc
	@echo "sepax $(VERSION) is installed in $(DESTDIR)$(PREFIX). To build and run a program with it:"
	@echo "  pkg-config finds it in /usr and /usr/local; elsewhere:"
	@echo "    export PKG_CONFIG_PATH=$(PREFIX)/lib/pkgconfig"
	@echo "  the loader must find libsepax.so.$(VERSION_MAJOR) at run time: either"
	@echo "    - run ldconfig (as root) once after installing into a directory it searches (/usr/local/lib),"
	@echo "    - or link with -Wl,-rpath,$(PREFIX)/lib (or run with LD_LIBRARY_PATH=$(PREFIX)/lib),"
	@echo "    - or link statically: $(PREFIX)/lib/libsepax.a -lm"
	@echo "  make uninstall PREFIX=$(PREFIX) removes it."

uninstall:
	rm -f $(addprefix $(DESTDIR)$(PREFIX)/,$(filter-out include/sepax/*.h,$(INSTALL_FILES)))
	rm -f $(addprefix $(DESTDIR)$(PREFIX)/include/sepax/,$(notdir $(wildcard include/sepax/*.h)))
	-rmdir $(DESTDIR)$(PREFIX)/include/sepax $(DESTDIR)$(PREFIX)/share/sepax/ecs $(DESTDIR)$(PREFIX)/share/sepax 2>/dev/null

# ---- housekeeping --------------------------------------------------------------

FORMAT_FILES = $(wildcard include/sepax/*.h src/*.c src/*.h tests/*.c tests/*.h tests/internal/*.c tests/support/*.c \
                 tests/support/*.h samples/*.c bench/*.c bench/*.h ecs/*.c ecs/*.h)
# clang-format, or Debian's versioned name when only that is installed
CLANG_FORMAT ?= $(or $(shell command -v clang-format 2>/dev/null),$(shell command -v clang-format-14 2>/dev/null),clang-format)
format:
	$(CLANG_FORMAT) -i $(FORMAT_FILES)
format-check:
	$(CLANG_FORMAT) --dry-run --Werror $(FORMAT_FILES)

clean:
	rm -rf build

# One line per target; .ci/run checks that every .PHONY target is listed.
help:
	@echo "sepax make targets (variables: SX_REAL=double, SAN=1, SIMD=0 or avx2, V=1, PREFIX=..., FLECS_DIR=...)"
	@echo "  all, lib          build/libsepax.a and the versioned build/libsepax.so (the default)"
	@echo "  test              build the library and run every cmocka test, the documentation's examples and the sample"
	@echo "  check-exports     libsepax.so must export exactly the SX_API declarations of include/sepax/*.h"
	@echo "  check-layers      every include stays in its layer or below (base, shape, collide, world, ecs)"
	@echo "  file-map          each src/ file's layer, line count and concept, and the 15 longest functions"
	@echo "  check-headers     compile the public headers as C++"
	@echo "  doc-examples      compile and run the C blocks of README.md and the C/C++ blocks of ecs/sepax_flecs.h"
	@echo "  readme-example    the same as doc-examples (its former name)"
	@echo "  sample-pyramid    build and run samples/pyramid.c on a small pyramid"
	@echo "  stress            the hostile scenes with the 100,000-step long run"
	@echo "  determinism       the determinism and narrowphase hashes at -O0, -O2 and -O3 must agree"
	@echo "  mutate            the mutation check: each bug of tests/mutations.txt must fail a test (minutes)"
	@echo "  demo              the flecs demo: 8 simulated seconds, final frame in build/demo/final.svg"
	@echo "  flecs             fetch flecs 4 (cargo, or FLECS_DIR) and compile flecs.c"
	@echo "  bench             every benchmark: narrowphase, world scenes, flecs overhead (minutes)"
	@echo "  bench-scenes      the world scenes alone (scenes.csv, plots, REPORT.md in build/bench)"
	@echo "  bench-smoke       every benchmark for a few iterations only (a check that they run)"
	@echo "  bench-ecs         the flecs module's overhead over the plain world"
	@echo "  bench-ecs-smoke   the same for a few steps"
	@echo "  fuzz              the libFuzzer harnesses, FUZZ_SECONDS each (fuzz/README.md)"
	@echo "  fuzz-build        build the fuzz harnesses with clang only"
	@echo "  fuzz-merge        add the last fuzz run's new-coverage inputs to fuzz/corpus/"
	@echo "  deps-test         install cmocka when missing (Debian package, as root)"
	@echo "  deps-bench        install the benchmark peers when missing (Debian packages; Box2D v3 with cargo)"
	@echo "  deps-fuzz         install clang and libFuzzer when missing (Debian packages)"
	@echo "  install           headers, libraries, sepax.pc and the flecs module's source into PREFIX (/usr/local)"
	@echo "  uninstall         remove what install put into PREFIX"
	@echo "  format            clang-format every source file in place"
	@echo "  format-check      fail if a source file is not clang-formatted"
	@echo "  clean             remove build/"
	@echo "  help              this list"

-include $(OBJS:.o=.d) $(patsubst %.c,$(OUT)/obj/tests/%.d,$(notdir $(TEST_SRCS))) \
         $(TEST_SUPPORT_OBJS:.o=.d) $(BENCH_OBJS:.o=.d)
