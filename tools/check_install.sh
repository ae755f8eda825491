#!/usr/bin/env bash
# make install, uninstall and deb as a user and a packager would run them,
# into folders under BUILD/check-install (nothing system-wide):
#  - install to prefix A, then B: each prefix's .pc files name that prefix;
#  - the README examples built against B with pkg-config and run without
#    LD_LIBRARY_PATH (tools/check_readme_example.sh);
#  - a fully static program with `pkg-config --static`;
#  - DESTDIR staging: files under DESTDIR/usr, .pc files that say /usr;
#  - uninstall leaves no file behind;
#  - make deb: a package dpkg-deb reads, with both libraries, headers, .pc files.
# Usage: tools/check_install.sh BUILD   (run by make test)
set -euo pipefail
build=${1:-build}
mk() { ${MAKE:-make} --no-print-directory BUILD="$build" "$@" > "$root/make.log" 2>&1 || {
  cat "$root/make.log" >&2; fail "make $* failed"; }; }
fail() { echo "check_install: $*" >&2; exit 1; }
root=$(mkdir -p "$build" && cd "$build" && pwd)/check-install
rm -rf "$root"
mkdir -p "$root"
a=$root/prefix-a
b=$root/prefix-b
installed=(include/tumble.h include/tumble_math.h include/tumble_render.h lib/libtumble.a lib/libtumble.so lib/libtumble.so.0
  lib/libtumble-render.a lib/libtumble-render.so lib/libtumble-render.so.0
  lib/pkgconfig/tumble.pc lib/pkgconfig/tumble-render.pc)

mk install PREFIX="$a"
mk install PREFIX="$b"
for p in "$a" "$b"; do
  for f in "${installed[@]}"; do [ -e "$p/$f" ] || fail "make install PREFIX=$p did not install $f"; done
  for pc in tumble tumble-render; do
    grep -qx "prefix=$p" "$p/lib/pkgconfig/$pc.pc" || fail "$p/lib/pkgconfig/$pc.pc does not say prefix=$p"
    grep -q -- "-Wl,-rpath,\${libdir}" "$p/lib/pkgconfig/$pc.pc" || fail "$pc.pc in $p has no rpath"
  done
done
echo "== make install: prefix A then B, each prefix's tumble.pc and tumble-render.pc name it"

tools/check_readme_example.sh "$b"

# static: the core example, no shared library at all
export PKG_CONFIG_PATH=$b/lib/pkgconfig
awk '/^```c$/ {on=1; next} /^```$/ && on {exit} on' README.md > "$root/static.c"
# shellcheck disable=SC2046 # pkg-config's flags are words
${CC:-cc} -std=c17 -static "$root/static.c" $(pkg-config --static --cflags --libs tumble) -o "$root/static"
if readelf -d "$root/static" 2>/dev/null | grep -q NEEDED; then fail "the -static example needs shared libraries"; fi
env -u LD_LIBRARY_PATH "$root/static" > /dev/null || fail "the static example did not run"
echo "== static link: cc -static app.c \$(pkg-config --static --cflags --libs tumble) runs, no shared library"

mk install DESTDIR="$root/stage" PREFIX=/usr
for f in "${installed[@]}"; do [ -e "$root/stage/usr/$f" ] || fail "DESTDIR staging lacks usr/$f"; done
grep -qx "prefix=/usr" "$root/stage/usr/lib/pkgconfig/tumble-render.pc" || fail "staged .pc does not say /usr"
if grep -rq "$root" "$root/stage/usr/lib/pkgconfig"; then fail "staged .pc files name DESTDIR"; fi
if grep -q rpath "$root/stage/usr/lib/pkgconfig/tumble.pc"; then fail "/usr .pc files need no rpath"; fi
echo "== make install DESTDIR=... PREFIX=/usr: files under DESTDIR/usr, .pc files say /usr"

mk uninstall PREFIX="$a"
left=$(find "$a" ! -type d)
[ -z "$left" ] || fail "make uninstall left: $left"
echo "== make uninstall: nothing left in the prefix"

mk deb
deb=$(ls "$build"/libtumble_*.deb)
dpkg-deb --info "$deb" > "$root/info.txt"
for field in "Package: libtumble" "Depends: libc6, libosmesa6, libpng16-16" "Architecture: "; do
  grep -q "$field" "$root/info.txt" || fail "$deb: control has no '$field'"
done
dpkg-deb --contents "$deb" > "$root/contents.txt"
for f in "${installed[@]}"; do grep -q " \./usr/$f\( \|$\)" "$root/contents.txt" || fail "$deb lacks /usr/$f"; done
if grep -v ' root/root ' "$root/contents.txt" | grep -q .; then fail "$deb has files not owned by root"; fi
echo "== make deb: $(basename "$deb"), $(grep -c . "$root/contents.txt") entries, control and contents as expected"
rm -rf "$root"
