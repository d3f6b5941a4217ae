# The dem toolkit: one static library (lib/libdem.a) and small programs (bin/).
#
#   make            build the library and the programs
#   make check      build and run every test; ends with "N passed, N failed"
#   make check SANITIZE=1   the same under AddressSanitizer and UBSan
#   make check CC=clang     the same built by clang (in build/rel-clang)
#   make MPI=1      the programs on MPI (-DDEM_MPI and mpicc --showme flags, any CC; in build/rel-mpi,
#                   lib/par/par.c's MPI half); make check links
#                   demshot so (build/rel-mpicheck) and runs the MPI tests
#                   too when mpicc is installed (test_fe_ranks under mpirun,
#                   tests/cli/mpi.bats)
#   make demo       set up and run the main job on a bundled scene
#   make deps       install the Debian packages the build needs (as root)
#   make install    install under PREFIX (/usr/local); DESTDIR stages it
#   make installcheck   the command-line tests on the installed programs
#   make uninstall  remove what make install installed
#   make deb        build the Debian packages (tools/deb.sh) into build/deb
#   make fuzz       fuzz the readers with AFL++ (tests/fuzz: FUZZ_TIME seconds each)
#
# CFLAGS, CPPFLAGS and LDFLAGS, from the command line or the environment,
# are added to the toolkit's own flags (dpkg-buildflags' hardening, say).

VERSION  := 0.1.0
CC       ?= cc
PKGS     := gsl yaml-0.1 zlib

# Where make install puts things: the GNU directory variables.  The
# programs look for the material library in pkgdatadir, compiled in (and
# compiled again when it changes, so that `make && make install
# PREFIX=~/.local` installs programs that look in ~/.local/share/dem);
# DEM_DATA overrides it at run time (dem-scene(5)).
PREFIX       = /usr/local
prefix       = $(PREFIX)
exec_prefix  = $(prefix)
bindir       = $(exec_prefix)/bin
libdir       = $(exec_prefix)/lib
includedir   = $(prefix)/include
datarootdir  = $(prefix)/share
datadir      = $(datarootdir)
mandir       = $(datarootdir)/man
man1dir      = $(mandir)/man1
man5dir      = $(mandir)/man5
pkgdatadir   = $(datadir)/dem
pkgconfigdir = $(libdir)/pkgconfig
bashcompdir  = $(datadir)/bash-completion/completions

# a compiler other than the default builds beside it, never over it (AFL++'s
# afl-cc, for make fuzz, in build/rel-afl)
COMPILER := $(if $(findstring afl,$(notdir $(firstword $(CC)))),afl,$(if $(findstring clang,$(notdir $(firstword $(CC)))),clang,))
SAN      := $(filter 1,$(SANITIZE))
ifeq ($(SANITIZE),1)
BUILD    := build/san
OPT      := -O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=all
else
BUILD    := build/rel
OPT      := -O2 -g
endif
ifneq ($(COMPILER),)
BUILD    := $(BUILD)-$(COMPILER)
endif
# MPI=1: the build on MPI beside the others (explicit.h, "Ranks")
MPI_ON   := $(filter 1,$(MPI))
ifeq ($(MPI_ON),1)
BUILD    := $(BUILD)-mpi
endif
# OpenMPI's own flags (mpicc --showme), given to whichever CC builds: gcc
# and clang alike compile lib/par/par.c's MPI half
MPI_CFLAGS = $(shell mpicc --showme:compile 2>/dev/null)
MPI_LIBS   = $(shell mpicc --showme:link 2>/dev/null)
ifeq ($(COMPILER),clang)
# valgrind 3.19 (Debian 12) does not read clang's default DWARF 5
OPT      += -gdwarf-4
endif

DEM_CFLAGS := -std=c11 -Wall -Wextra -Werror $(OPT) -D_POSIX_C_SOURCE=200809L \
            -DDEM_VERSION='"$(VERSION)"' -Ilib -fopenmp $(if $(MPI_ON),-DDEM_MPI $(MPI_CFLAGS)) \
            $(shell pkg-config --cflags $(PKGS) 2>/dev/null) -I/usr/include/suitesparse
ALL_CFLAGS = $(DEM_CFLAGS) $(CPPFLAGS) $(CFLAGS)
# CHOLMOD (SuiteSparse) has no pkg-config file on Debian 12
LDLIBS   := $(shell pkg-config --libs $(PKGS) 2>/dev/null) -lcholmod -lm $(if $(MPI_ON),$(MPI_LIBS))
ALL_LDFLAGS = $(filter -fsanitize% -fno-sanitize%,$(OPT)) -fopenmp $(LDFLAGS)

LIB_SRC  := $(sort $(wildcard lib/*/*.c))
LIB_OBJ  := $(LIB_SRC:%.c=$(BUILD)/%.o)
CMD_SRC  := $(sort $(wildcard cmd/*.c))
PROGS    := $(CMD_SRC:cmd/%.c=$(BUILD)/bin/%)
TEST_SRC := $(sort $(wildcard tests/unit/test_*.c))
TESTS    := $(TEST_SRC:tests/unit/%.c=$(BUILD)/tests/%)
# the readers' fuzzing harness: make check replays tests/fuzz/corpus with
# it, make fuzz runs it under AFL++
FUZZER   := $(BUILD)/tests/fuzz-readers
# bash completion, made from each program's --help (tools/completion.sh)
COMPLETIONS := $(PROGS:$(BUILD)/bin/%=$(BUILD)/completion/%)

ifneq ($(SAN)$(COMPILER)$(MPI_ON),)
LIBDEM   := $(BUILD)/lib/libdem.a
BUILDBIN := $(BUILD)/bin
else
LIBDEM   := lib/libdem.a
BUILDBIN := bin
endif

.PHONY: all deps build check test demo clean bench FORCE mpi-build \
        install uninstall installcheck deb fuzz
.SUFFIXES:
.SECONDARY:

all: deps
	@$(MAKE) --no-print-directory build

build: $(LIBDEM) $(PROGS:$(BUILD)/bin/%=$(BUILDBIN)/%) $(COMPLETIONS) $(BUILD)/dem.pc

deps:
	@sh tools/deps.sh

$(BUILD)/%.o: %.c
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) $(DATADIR_DEF) -MMD -MP -c $< -o $@

# the compiled-in data directory: only share.o holds it, remade when the
# file below changes (it is rewritten only then)
$(BUILD)/lib/core/share.o: DATADIR_DEF = -DDEM_DATADIR='"$(pkgdatadir)"'
$(BUILD)/lib/core/share.o: $(BUILD)/pkgdatadir
$(BUILD)/pkgdatadir: FORCE
	@mkdir -p $(@D)
	@echo '$(pkgdatadir)' | cmp -s - $@ || echo '$(pkgdatadir)' > $@

$(LIBDEM): $(LIB_OBJ)
	@mkdir -p $(@D)
	rm -f $@ && ar rcs $@ $^

$(BUILD)/bin/%: $(BUILD)/cmd/%.o $(LIBDEM)
	@mkdir -p $(@D)
	$(CC) $(ALL_LDFLAGS) $< $(LIBDEM) $(LDLIBS) -o $@

ifeq ($(SAN)$(COMPILER)$(MPI_ON),)
bin/%: $(BUILD)/bin/%
	@mkdir -p bin
	cp $< $@.tmp && mv -f $@.tmp $@
endif

$(BUILD)/completion/%: $(BUILD)/bin/% tools/completion.sh
	@mkdir -p $(@D)
	sh tools/completion.sh $< > $@.tmp && mv -f $@.tmp $@

$(BUILD)/tests/%: $(BUILD)/tests/unit/%.o $(LIBDEM)
	@mkdir -p $(@D)
	$(CC) $(ALL_LDFLAGS) $< $(LIBDEM) $(LDLIBS) -lcmocka -o $@

$(FUZZER): $(BUILD)/tests/fuzz/fuzz.o $(LIBDEM)
	@mkdir -p $(@D)
	$(CC) $(ALL_LDFLAGS) $< $(LIBDEM) $(LDLIBS) -o $@

# AFL++ on each reader for FUZZ_TIME seconds (tests/fuzz/run.sh: builds
# with afl-cc under ASan and UBSan into build/rel-afl, keeps what crashes in
# tests/fuzz/corpus, writes tests/fuzz/REPORT.md).  Not part of make deps:
# it installs afl++ itself when missing (as root).
FUZZ_TIME    = 600
FUZZ_TARGETS = stream scene state profile bodies
fuzz:
	@sh tests/fuzz/run.sh "$(FUZZ_TIME)" $(FUZZ_TARGETS)

# what the tests need to know besides PATH: where the completions are, the
# compiler, and where make install puts things (tests/install)
TEST_ENV = DEM_TEST_COMPDIR="$(abspath $(BUILD)/completion)" DEM_TEST_CC="$(CC)" \
           DEM_TEST_DIRS="prefix=$(prefix) bindir=$(bindir) libdir=$(libdir) \
             includedir=$(includedir) mandir=$(mandir) pkgdatadir=$(pkgdatadir) \
             pkgconfigdir=$(pkgconfigdir) bashcompdir=$(bashcompdir)"

# make check builds on every core unless make was given -j itself
CHECK_JOBS = $(shell nproc 2>/dev/null || echo 1)
check: deps
	@$(MAKE) --no-print-directory $(if $(filter -j%,$(MAKEFLAGS)),,-j$(CHECK_JOBS)) test

# make check also builds demshot and the MPI unit tests on MPI (in
# build/rel-mpicheck) and runs them when mpicc is installed (make deps
# installs OpenMPI): in the plain build only, not under SANITIZE, another CC
# or MPI=1.  They are the plain build's objects with lib/par/par.o replaced
# by its MPI build (par.c again with -DDEM_MPI, the one file it changes),
# linked with OpenMPI: a minute of CI less than compiling everything again
# (`make MPI=1` does that)
MPICC    := $(if $(SAN)$(COMPILER)$(MPI_ON),,$(shell command -v mpicc 2>/dev/null))
MPI_DIR  := build/rel-mpicheck
MPI_LIB  := $(MPI_DIR)/libdem.a
MPI_TESTS := test_fe_ranks
MPI_ENV  = $(if $(MPICC),DEM_TEST_MPIBIN="$(abspath $(MPI_DIR)/bin)" \
             DEM_TEST_MPITESTS="$(MPI_TESTS:%=$(abspath $(MPI_DIR)/tests)/%)")

# check without make deps (the Debian package build runs this one)
test: build $(TESTS) $(FUZZER) $(if $(MPICC),mpi-build)
	@$(TEST_ENV) $(MPI_ENV) sh tests/run.sh "$(BUILD)/tests" "$(abspath $(BUILDBIN))" "$(SANITIZE)" \
	  tests/cli tests/install/staged.bats

mpi-build: $(MPI_DIR)/bin/demshot $(MPI_TESTS:%=$(MPI_DIR)/tests/%)

ifneq ($(MPICC),)
$(MPI_DIR)/par.o: lib/par/par.c
	@mkdir -p $(@D)
	$(CC) $(ALL_CFLAGS) -DDEM_MPI $(MPI_CFLAGS) -MMD -MP -c $< -o $@

$(MPI_LIB): $(filter-out $(BUILD)/lib/par/par.o,$(LIB_OBJ)) $(MPI_DIR)/par.o
	rm -f $@ && ar rcs $@ $^

$(MPI_DIR)/bin/demshot: $(BUILD)/cmd/demshot.o $(MPI_LIB)
	@mkdir -p $(@D)
	$(CC) $(ALL_LDFLAGS) $< $(MPI_LIB) $(LDLIBS) $(MPI_LIBS) -o $@

$(MPI_DIR)/tests/%: $(BUILD)/tests/unit/%.o $(MPI_LIB)
	@mkdir -p $(@D)
	$(CC) $(ALL_LDFLAGS) $< $(MPI_LIB) $(LDLIBS) $(MPI_LIBS) -lcmocka -o $@

-include $(MPI_DIR)/par.d
endif

demo: deps
	@$(MAKE) --no-print-directory build
	@$(MAKE) --no-print-directory -C examples/demo

bench: all
	@$(MAKE) --no-print-directory -C examples/detect-bench

clean:
	rm -rf build bin lib/libdem.a

# ---- install -----------------------------------------------------------
# What goes where, one line a folder: MODE FOLDER FILE...; tools/install.sh
# installs and uninstalls by it.  The bundled scenes are the examples'
# (examples/NAME/X.yaml -> $(pkgdatadir)/scenes/NAME/X.yaml).
HEADERS_PRIVATE := lib/contact/vec3.h lib/detect/dcell_impl.h \
                   lib/detect/dcell_sweep.h lib/detect/tree_impl.h \
                   lib/fe/simd.h lib/fe/ckpt.h lib/fe/cdiff.h lib/mesh/hex.h
HEADERS  := $(filter-out $(HEADERS_PRIVATE),$(sort $(wildcard lib/*/*.h)))
SCENES   := $(sort $(wildcard examples/*/*.yaml examples/verification/laws-mat/*.yaml))
# $(call in_dir,DIR/,FILES): the FILES right in DIR (not below it)
in_dir = $(foreach f,$(2),$(if $(filter $(1),$(dir $(f))),$(f)))
define nl


endef
define INSTALL_PLAN
755 $(bindir) $(PROGS)
644 $(man1dir) $(sort $(wildcard man/man1/*.1))
644 $(man5dir) $(sort $(wildcard man/man5/*.5))
644 $(pkgdatadir) share/README.md
644 $(pkgdatadir)/materials $(sort $(wildcard share/materials/*.yaml))
644 $(pkgdatadir)/shots $(sort $(wildcard share/shots/*.yaml))
$(foreach d,$(sort $(dir $(SCENES))),644 $(pkgdatadir)/scenes/$(d:examples/%/=%) $(call in_dir,$(d),$(SCENES))$(nl))
644 $(libdir) $(LIBDEM)
$(foreach d,$(sort $(dir $(HEADERS))),644 $(includedir)/dem/$(d:lib/%/=%) $(call in_dir,$(d),$(HEADERS))$(nl))
644 $(pkgconfigdir) $(BUILD)/dem.pc
644 $(bashcompdir) $(COMPLETIONS)
endef
export INSTALL_PLAN

# dem.pc for the folders of this make (rewritten only when they change)
PC_SED = sed -e 's|@prefix@|$(prefix)|g' -e 's|@libdir@|$(libdir)|g' \
             -e 's|@includedir@|$(includedir)|g' -e 's|@pkgdatadir@|$(pkgdatadir)|g' \
             -e 's|@version@|$(VERSION)|g' lib/dem.pc.in
$(BUILD)/dem.pc: lib/dem.pc.in FORCE
	@mkdir -p $(@D)
	@$(PC_SED) | cmp -s - $@ || $(PC_SED) > $@

install: build
	@sh tools/install.sh install "$(DESTDIR)" "$(pkgdatadir)"

uninstall:
	@sh tools/install.sh uninstall "$(DESTDIR)" "$(pkgdatadir)"

# the command-line tests on the installed programs: PATH is the installed
# bin/ and the system's, the scenes and the library are the installed ones
# (through the compiled-in path; with DESTDIR, through DEM_DATA)
installcheck:
	@$(TEST_ENV) DEM_TEST_INSTALLED=1 \
	  DEM_TEST_COMPDIR="$(DESTDIR)$(bashcompdir)" \
	  DEM_TEST_DATA="$(DESTDIR)$(pkgdatadir)" \
	  DEM_TEST_MANDIR="$(DESTDIR)$(mandir)" \
	  DEM_TEST_DESTDIR="$(DESTDIR)" \
	  sh tests/run.sh "" "$(DESTDIR)$(bindir)" "" tests/cli tests/install/installed.bats

deb:
	@sh tools/deb.sh build/deb

-include $(LIB_OBJ:.o=.d) $(CMD_SRC:cmd/%.c=$(BUILD)/cmd/%.d) $(TEST_SRC:tests/unit/%.c=$(BUILD)/tests/unit/%.d) \
         $(BUILD)/tests/fuzz/fuzz.d
