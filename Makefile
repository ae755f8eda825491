# tumble: plain Makefile. `make` builds the libraries; `make test`, `make demo`,
# `make sanitize`, `make install` are the other entry points (see README.md).

CC ?= cc
CXX ?= c++
PREFIX ?= /usr/local
DESTDIR ?=

ifeq ($(DEBUG),1)
  BUILD ?= build/debug
  OPT := -O0 -g
else
  BUILD ?= build
  OPT := -O2
endif

WARN := -Wall -Wextra -Wpedantic -Werror
CFLAGS_ALL := -std=c17 $(WARN) -ffp-contract=off $(OPT) -fPIC -Iinclude -MMD -MP $(EXTRA_CFLAGS)
CXXFLAGS_ALL := -std=c++17 $(WARN) -ffp-contract=off $(OPT) -Iinclude -MMD -MP $(EXTRA_CFLAGS)
LDLIBS_ALL := -lm $(EXTRA_LDFLAGS)

LIB_SRC := $(wildcard src/*.c)
LIB_OBJ := $(LIB_SRC:%.c=$(BUILD)/obj/%.o)
LIB_A := $(BUILD)/libtumble.a
LIB_SO := $(BUILD)/libtumble.so

# one check executable per suite; reference suites also link the Box2D shim
UNIT_SRC := $(filter-out tests/test_util.c,$(wildcard tests/test_*.c))
UNIT_BIN := $(UNIT_SRC:tests/%.c=$(BUILD)/tests/%)
REF_SRC := $(wildcard tests/reference/test_*.c)
REF_BIN := $(REF_SRC:tests/reference/%.c=$(BUILD)/tests/reference/%)
SHIM_SRC := $(wildcard tests/reference/*.cpp)
SHIM_OBJ := $(SHIM_SRC:%.cpp=$(BUILD)/obj/%.o)
TEST_UTIL_OBJ := $(BUILD)/obj/tests/test_util.o

CHECK_CFLAGS = $(shell pkg-config --cflags check 2>/dev/null)
CHECK_LIBS = $(shell pkg-config --libs check 2>/dev/null || echo -lcheck)

# keep test and shim objects between builds (they are intermediate files otherwise)
.SECONDARY:

.PHONY: all lib test tests sanitize install uninstall clean format format-check deps-test

# Each area has its own fragment in mk/ (demo, bench, stress, fuzz, ...). A
# fragment may add to these hooks:
#   EXTRA_TEST_BIN   suites that `make test` builds and runs after the unit and
#                    reference suites (e.g. the renderer tests, the stress subset)
#   EXTRA_TEST_DEPS  tools/deps.sh groups `make test` needs besides `test`
#   EXTRA_SAN_BIN    suites that `make sanitize` builds (under build/sanitize) and runs
#   FORMATTED        sources that `make format` and `make format-check` cover
.DEFAULT_GOAL := all
EXTRA_TEST_BIN :=
EXTRA_TEST_DEPS :=
EXTRA_SAN_BIN :=
# The scene catalogue (demos/scenes: scenes.c lists the scenes, gallery.c
# builds the demo ones), linked whole by the demos, the bench and the tests.
SCENE_CATALOGUE_OBJ := $(patsubst %.c,$(BUILD)/obj/%.o,$(wildcard demos/scenes/*.c))
include $(sort $(wildcard mk/*.mk))

all: lib

lib: $(LIB_A) $(LIB_SO)

$(BUILD)/obj/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_ALL) $(CHECK_INC) -c $< -o $@

$(BUILD)/obj/%.o: %.cpp
	@mkdir -p $(dir $@)
	$(CXX) $(CXXFLAGS_ALL) -c $< -o $@

$(LIB_A): $(LIB_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@
	ar rcs $@ $^

$(LIB_SO): $(LIB_OBJ)
	@mkdir -p $(dir $@)
	$(CC) -shared $(EXTRA_CFLAGS) -Wl,-soname,libtumble.so.0 -o $@ $^ $(LDLIBS_ALL)

# ---- tests -------------------------------------------------------------------
# Test objects need check's include flags; computed only when tests are built.
$(BUILD)/obj/tests/%.o: CHECK_INC = $(CHECK_CFLAGS)

$(BUILD)/tests/%: $(BUILD)/obj/tests/%.o $(TEST_UTIL_OBJ) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(EXTRA_CFLAGS) -o $@ $< $(TEST_UTIL_OBJ) $(LIB_A) $(CHECK_LIBS) $(LDLIBS_ALL)

$(BUILD)/tests/reference/%: $(BUILD)/obj/tests/reference/%.o $(SHIM_OBJ) $(TEST_UTIL_OBJ) $(LIB_A)
	@mkdir -p $(dir $@)
	$(CXX) $(EXTRA_CFLAGS) -o $@ $< $(SHIM_OBJ) $(TEST_UTIL_OBJ) $(LIB_A) -lbox2d $(CHECK_LIBS) $(LDLIBS_ALL)

deps-test:
	@tools/deps.sh test $(EXTRA_TEST_DEPS)

tests: $(UNIT_BIN) $(REF_BIN)

# The deps check runs first, alone; then the suites build and run.
test: deps-test
	@$(MAKE) --no-print-directory tests $(BUILD)/tools/determinism $(EXTRA_TEST_BIN)
	@$(MAKE) --no-print-directory DEBUG=1 build/debug/tools/determinism
	@tools/run_tests.sh $(UNIT_BIN) $(REF_BIN) $(EXTRA_TEST_BIN)
	@tools/check_readme_example.sh $(BUILD)
	@tools/check_determinism.sh $(BUILD)/tools/determinism build/debug/tools/determinism

# One scene hashed after 1,000 steps; make test compares an -O0 and an -O2 build.
$(BUILD)/tools/determinism: $(BUILD)/obj/tools/determinism.o $(LIB_A)
	@mkdir -p $(dir $@)
	$(CC) $(EXTRA_CFLAGS) -o $@ $< $(LIB_A) $(LDLIBS_ALL)

# Same suites with AddressSanitizer and UndefinedBehaviorSanitizer, in-process
# (CK_FORK=no) so that LeakSanitizer sees every test's allocations.
# tools/lsan.supp holds OSMesa's own leak (the render suite), nothing else.
SAN := -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all
sanitize: deps-test
	@$(MAKE) --no-print-directory BUILD=build/sanitize EXTRA_CFLAGS="$(SAN)" tests \
	  $(EXTRA_SAN_BIN:$(BUILD)/%=build/sanitize/%)
	@CK_FORK=no ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  LSAN_OPTIONS=suppressions=$(abspath tools/lsan.supp) \
	  tools/run_tests.sh $(UNIT_SRC:tests/%.c=build/sanitize/tests/%) $(REF_SRC:tests/reference/%.c=build/sanitize/tests/reference/%) \
	  $(EXTRA_SAN_BIN:$(BUILD)/%=build/sanitize/%)

# ---- install -------------------------------------------------------------------
$(BUILD)/tumble.pc: tools/tumble.pc.in Makefile
	@mkdir -p $(dir $@)
	sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@VERSION@|0.1.0|g' $< > $@

install: lib $(BUILD)/tumble.pc
	install -d $(DESTDIR)$(PREFIX)/include $(DESTDIR)$(PREFIX)/lib/pkgconfig
	install -m 644 include/tumble.h $(DESTDIR)$(PREFIX)/include/tumble.h
	install -m 644 include/tumble_math.h $(DESTDIR)$(PREFIX)/include/tumble_math.h
	install -m 644 $(LIB_A) $(DESTDIR)$(PREFIX)/lib/libtumble.a
	install -m 755 $(LIB_SO) $(DESTDIR)$(PREFIX)/lib/libtumble.so.0
	ln -sf libtumble.so.0 $(DESTDIR)$(PREFIX)/lib/libtumble.so
	install -m 644 $(BUILD)/tumble.pc $(DESTDIR)$(PREFIX)/lib/pkgconfig/tumble.pc
	-@[ -z "$(DESTDIR)" ] && command -v ldconfig >/dev/null && [ "$$(id -u)" = 0 ] && ldconfig || true

uninstall:
	rm -f $(DESTDIR)$(PREFIX)/include/tumble_math.h
	rm -f $(DESTDIR)$(PREFIX)/include/tumble.h $(DESTDIR)$(PREFIX)/lib/libtumble.a \
	  $(DESTDIR)$(PREFIX)/lib/libtumble.so $(DESTDIR)$(PREFIX)/lib/libtumble.so.0 \
	  $(DESTDIR)$(PREFIX)/lib/pkgconfig/tumble.pc

FORMATTED += include/*.h src/*.c src/*.h tests/*.c tests/*.h tests/reference/*.c tests/reference/*.cpp \
  tests/reference/*.h demos/*.c demos/scenes/*.c demos/scenes/*.h tools/*.c tools/*.cpp
format:
	clang-format -i $(FORMATTED)

format-check:
	clang-format --dry-run --Werror $(FORMATTED)

clean:
	rm -rf build

-include $(shell find build -name '*.d' 2>/dev/null)
