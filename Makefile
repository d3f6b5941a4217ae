# The dem toolkit: one static library (lib/libdem.a) and small programs (bin/).
#
#   make            build the library and the programs
#   make check      build and run every test; ends with "N passed, N failed"
#   make check SANITIZE=1   the same under AddressSanitizer and UBSan
#   make check CC=clang     the same built by clang (in build/rel-clang)
#   make demo       set up and run the main job on a bundled scene
#   make deps       install the Debian packages the build needs (as root)

VERSION  := 0.1.0
CC       ?= cc
# where an installed toolkit finds its share/ (material and shot libraries)
DATADIR  ?= /usr/local/share/dem
PKGS     := gsl yaml-0.1 zlib

# a compiler other than the default builds beside it, never over it
COMPILER := $(if $(findstring clang,$(notdir $(firstword $(CC)))),clang,)
SAN      := $(filter 1,$(SANITIZE))
ifeq ($(SANITIZE),1)
BUILD    := build/san
OPT      := -O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=all
else
BUILD    := build/rel
OPT      := -O2 -g
endif
ifeq ($(COMPILER),clang)
BUILD    := $(BUILD)-clang
# valgrind 3.19 (Debian 12) does not read clang's default DWARF 5
OPT      += -gdwarf-4
endif

CFLAGS   := -std=c11 -Wall -Wextra -Werror $(OPT) -D_POSIX_C_SOURCE=200809L \
            -DDEM_VERSION='"$(VERSION)"' -DDEM_DATADIR='"$(DATADIR)"' \
            -Ilib -fopenmp \
            $(shell pkg-config --cflags $(PKGS) 2>/dev/null) -I/usr/include/suitesparse
# CHOLMOD (SuiteSparse) has no pkg-config file on Debian 12
LDLIBS   := $(shell pkg-config --libs $(PKGS) 2>/dev/null) -lcholmod -lm
LDFLAGS  := $(filter -fsanitize% -fno-sanitize%,$(OPT)) -fopenmp

LIB_SRC  := $(sort $(wildcard lib/*/*.c))
LIB_OBJ  := $(LIB_SRC:%.c=$(BUILD)/%.o)
CMD_SRC  := $(sort $(wildcard cmd/*.c))
PROGS    := $(CMD_SRC:cmd/%.c=$(BUILD)/bin/%)
TEST_SRC := $(sort $(wildcard tests/unit/test_*.c))
TESTS    := $(TEST_SRC:tests/unit/%.c=$(BUILD)/tests/%)

ifneq ($(SAN)$(COMPILER),)
LIBDEM   := $(BUILD)/lib/libdem.a
BINDIR   := $(BUILD)/bin
else
LIBDEM   := lib/libdem.a
BINDIR   := bin
endif

.PHONY: all deps build check unit cli demo clean bench
.SUFFIXES:
.SECONDARY:

all: deps
	@$(MAKE) --no-print-directory build

build: $(LIBDEM) $(PROGS:$(BUILD)/bin/%=$(BINDIR)/%)

deps:
	@sh tools/deps.sh

$(BUILD)/%.o: %.c
	@mkdir -p $(@D)
	$(CC) $(CFLAGS) -MMD -MP -c $< -o $@

$(LIBDEM): $(LIB_OBJ)
	@mkdir -p $(@D)
	rm -f $@ && ar rcs $@ $^

$(BUILD)/bin/%: $(BUILD)/cmd/%.o $(LIBDEM)
	@mkdir -p $(@D)
	$(CC) $(LDFLAGS) $< $(LIBDEM) $(LDLIBS) -o $@

ifeq ($(SAN)$(COMPILER),)
bin/%: $(BUILD)/bin/%
	@mkdir -p bin
	cp $< $@.tmp && mv -f $@.tmp $@
endif

$(BUILD)/tests/%: $(BUILD)/tests/unit/%.o $(LIBDEM)
	@mkdir -p $(@D)
	$(CC) $(LDFLAGS) $< $(LIBDEM) $(LDLIBS) -lcmocka -o $@

check: deps
	@$(MAKE) --no-print-directory build $(TESTS)
	@sh tests/run.sh "$(BUILD)/tests" "$(abspath $(BINDIR))" "$(SANITIZE)"

demo: deps
	@$(MAKE) --no-print-directory build
	@$(MAKE) --no-print-directory -C examples/demo

bench: all
	@$(MAKE) --no-print-directory -C examples/detect-bench

clean:
	rm -rf build bin lib/libdem.a

-include $(LIB_OBJ:.o=.d) $(CMD_SRC:cmd/%.c=$(BUILD)/cmd/%.d) $(TEST_SRC:tests/unit/%.c=$(BUILD)/tests/unit/%.d)
