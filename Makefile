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
  # -O3, as Box2D v3's Release build: with -ffp-contract=off and no fast-math
  # the compiler may not reorder or fuse float operations, so it computes the
  # same bits as -O0 (make test checks that), 0.93 to 0.99 times -O2's time
  # on the ten v3 scenes (docs/bench/V3.md).
  OPT := -O3
endif

WARN := -Wall -Wextra -Wpedantic -Werror
CFLAGS_ALL := -std=c17 $(WARN) -ffp-contract=off $(OPT) -fPIC -Iinclude -MMD -MP $(EXTRA_CFLAGS)
CXXFLAGS_ALL := -std=c++17 $(WARN) -ffp-contract=off $(OPT) -Iinclude -MMD -MP $(EXTRA_CFLAGS)
LDLIBS_ALL := -lm $(EXTRA_LDFLAGS)

LIB_SRC := $(wildcard src/*.c)
LIB_OBJ := $(LIB_SRC:%.c=$(BUILD)/obj/%.o)
LIB_A := $(BUILD)/libtumble.a
LIB_SO := $(BUILD)/libtumble.so

# The headless renderer (render/, public header include/tumble_render.h): a
# second installed library, on OSMesa (software OpenGL; never also -lGL,
# whose symbols would clash) and libpng (tools/deps.sh demo installs them).
# `make render` builds it; the demos, their tests and `make install` use it.
RENDER_PKGS := osmesa libpng
RENDER_CFLAGS = $(shell pkg-config --cflags $(RENDER_PKGS) 2>/dev/null)
RENDER_LIBS = $(shell pkg-config --libs $(RENDER_PKGS) 2>/dev/null || echo -lOSMesa -lpng)
RENDER_LIB_SRC := $(wildcard render/*.c)
RENDER_LIB_OBJ := $(RENDER_LIB_SRC:%.c=$(BUILD)/obj/%.o)
RENDER_LIB_A := $(BUILD)/libtumble-render.a
RENDER_LIB_SO := $(BUILD)/libtumble-render.so
VERSION := 0.1.0

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

.PHONY: all lib render test tests sanitize install uninstall deb clean format format-check deps-test deps-render

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

deps-render:
	@tools/deps.sh demo

# both libraries: libtumble-render needs libtumble.so to link
render: deps-render
	@$(MAKE) --no-print-directory $(LIB_A) $(LIB_SO) $(RENDER_LIB_A) $(RENDER_LIB_SO)

$(BUILD)/obj/render/%.o: render/%.c
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS_ALL) $(RENDER_CFLAGS) -c $< -o $@

$(RENDER_LIB_A): $(RENDER_LIB_OBJ)
	@mkdir -p $(dir $@)
	rm -f $@
	ar rcs $@ $^

# Needs libtumble.so.0 at run time (linked against build/libtumble.so).
$(RENDER_LIB_SO): $(RENDER_LIB_OBJ) $(LIB_SO)
	@mkdir -p $(dir $@)
	$(CC) -shared $(EXTRA_CFLAGS) -Wl,-soname,libtumble-render.so.0 -o $@ $(RENDER_LIB_OBJ) \
	  -L$(BUILD) -ltumble $(RENDER_LIBS) $(LDLIBS_ALL)

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
	@MAKE="$(MAKE)" tools/check_install.sh $(BUILD)
	@tools/check_determinism.sh $(BUILD)/tools/determinism build/debug/tools/determinism

# One scene hashed after 1,000 steps; make test compares an -O0 and an -O3 build.
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
# Both libraries, their headers and pkg-config files. The .pc files are written
# by each install from that call's PREFIX (never a copy kept in build/), so
# `make install PREFIX=B` after PREFIX=A names B. Their Libs carry
# -Wl,-rpath,${libdir} unless PREFIX is /usr (the loader's default path): a
# program linked with `pkg-config --libs` runs without LD_LIBRARY_PATH from
# any prefix. As root without DESTDIR, ldconfig also refreshes the loader's
# cache (for programs linked without pkg-config, in /usr/local).
comma := ,
PC_RPATH = $(if $(filter /usr /usr/,$(PREFIX)),,-Wl$(comma)-rpath$(comma)$${libdir} )
PC_SED = sed -e 's|@PREFIX@|$(PREFIX)|g' -e 's|@VERSION@|$(VERSION)|g' -e 's|@RPATH@|$(PC_RPATH)|g'
INSTALL_INC = $(DESTDIR)$(PREFIX)/include
INSTALL_LIB = $(DESTDIR)$(PREFIX)/lib

install: render
	install -d $(INSTALL_INC) $(INSTALL_LIB)/pkgconfig
	install -m 644 include/tumble.h $(DESTDIR)$(PREFIX)/include/tumble.h
	install -m 644 include/tumble_math.h $(INSTALL_INC)/tumble_math.h
	install -m 644 include/tumble_render.h $(INSTALL_INC)/tumble_render.h
	install -m 644 $(LIB_A) $(INSTALL_LIB)/libtumble.a
	install -m 755 $(LIB_SO) $(INSTALL_LIB)/libtumble.so.0
	ln -sf libtumble.so.0 $(INSTALL_LIB)/libtumble.so
	install -m 644 $(RENDER_LIB_A) $(INSTALL_LIB)/libtumble-render.a
	install -m 755 $(RENDER_LIB_SO) $(INSTALL_LIB)/libtumble-render.so.0
	ln -sf libtumble-render.so.0 $(INSTALL_LIB)/libtumble-render.so
	$(PC_SED) tools/tumble.pc.in > $(INSTALL_LIB)/pkgconfig/tumble.pc
	$(PC_SED) tools/tumble-render.pc.in > $(INSTALL_LIB)/pkgconfig/tumble-render.pc
	-@[ -z "$(DESTDIR)" ] && command -v ldconfig >/dev/null && [ "$$(id -u)" = 0 ] && ldconfig || true

uninstall:
	rm -f $(INSTALL_INC)/tumble_math.h
	rm -f $(DESTDIR)$(PREFIX)/include/tumble.h $(INSTALL_INC)/tumble_render.h \
	  $(INSTALL_LIB)/libtumble.a $(INSTALL_LIB)/libtumble.so $(INSTALL_LIB)/libtumble.so.0 \
	  $(INSTALL_LIB)/libtumble-render.a $(INSTALL_LIB)/libtumble-render.so $(INSTALL_LIB)/libtumble-render.so.0 \
	  $(INSTALL_LIB)/pkgconfig/tumble.pc $(INSTALL_LIB)/pkgconfig/tumble-render.pc
	-@[ -z "$(DESTDIR)" ] && command -v ldconfig >/dev/null && [ "$$(id -u)" = 0 ] && ldconfig || true

# One Debian package (libtumble: both libraries, headers, .pc files under
# /usr) built with dpkg-deb into build/; dpkg runs ldconfig through a trigger.
DEB_ARCH = $(shell dpkg --print-architecture 2>/dev/null || echo amd64)
DEB_ROOT = $(BUILD)/deb/root
deb: render
	rm -rf $(BUILD)/deb
	@$(MAKE) --no-print-directory install DESTDIR=$(abspath $(DEB_ROOT)) PREFIX=/usr
	mkdir -p $(DEB_ROOT)/DEBIAN
	printf '%s\n' 'Package: libtumble' 'Version: $(VERSION)' 'Architecture: $(DEB_ARCH)' \
	  'Maintainer: tumble developers <tumble@localhost>' 'Section: libdevel' 'Priority: optional' \
	  'Depends: libc6, libosmesa6, libpng16-16' "Installed-Size: $$(du -sk $(DEB_ROOT)/usr | cut -f1)" \
	  'Description: 2D rigid-body physics engine for games' \
	  ' libtumble, the engine (C17, libc and libm only), and libtumble-render, headless' \
	  ' pictures and videos of its worlds (OSMesa, libpng), with their headers and' \
	  ' pkg-config files (tumble, tumble-render).' > $(DEB_ROOT)/DEBIAN/control
	echo 'activate-noawait ldconfig' > $(DEB_ROOT)/DEBIAN/triggers
	cd $(DEB_ROOT) && find usr -type f | sort | xargs md5sum > DEBIAN/md5sums
	dpkg-deb --root-owner-group --build $(DEB_ROOT) $(BUILD)/libtumble_$(VERSION)_$(DEB_ARCH).deb

FORMATTED += include/*.h src/*.c src/*.h tests/*.c tests/*.h tests/reference/*.c tests/reference/*.cpp \
  tests/reference/*.h demos/*.c demos/scenes/*.c demos/scenes/*.h tools/*.c tools/*.cpp
format:
	clang-format -i $(FORMATTED)

format-check:
	clang-format --dry-run --Werror $(FORMATTED)

clean:
	rm -rf build

# header dependencies of every build tree, also one outside build/ (BUILD=...):
# without them a changed header left that tree's objects stale
-include $(sort $(shell find build $(BUILD) -name '*.d' 2>/dev/null))
