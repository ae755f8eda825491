#!/usr/bin/env bash
# Installs the Debian packages a make target needs, only when they are missing.
# Usage: tools/deps.sh GROUP...   (groups: test, sanitize, demo (also the renderer library and make install), viewer, video, bench, fuzz, valgrind)
# Idempotent: a package that dpkg reports as installed is never touched again.
# The library itself needs nothing from here: only a C compiler and libm.
set -euo pipefail

want=()
why=()
add() { want+=("$1"); why+=("$2"); }

for group in "$@"; do
  case "$group" in
    test | sanitize)
      add check "the unit-test framework (libcheck)"
      add libbox2d-dev "Box2D 2.4.1, the reference the tests compare against"
      add g++ "compiles the small C++ shim around Box2D"
      add pkg-config "finds the compile and link flags of check"
      ;;
    demo)
      add libosmesa6-dev "off-screen OpenGL rendering (libtumble-render, the demos)"
      add libpng-dev "writes the rendered pictures as PNG (libtumble-render)"
      add pkg-config "finds the compile and link flags of OSMesa and libpng"
      ;;
    viewer) add libsdl2-dev "the optional interactive viewer" ;;
    bench)
      add libbox2d-dev "Box2D 2.4.1, run side by side in the benchmark"
      add g++ "compiles the small C++ shim around Box2D"
      add gnuplot-nox "draws the run-time-against-error plots"
      ;;
    video) add ffmpeg "turns rendered frame sequences into MP4 and GIF (optional)" ;;
    fuzz) add clang "libFuzzer harnesses" ;;
    valgrind) add valgrind "memcheck over the test suite" ;;
    *) echo "deps.sh: unknown group '$group' (known: test sanitize demo viewer video bench fuzz valgrind)" >&2; exit 2 ;;
  esac
done

missing=()
for i in "${!want[@]}"; do
  pkg=${want[$i]}
  if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q 'install ok installed'; then
    case " ${missing[*]-} " in *" $pkg "*) ;; *)
      missing+=("$pkg")
      echo "deps.sh: installing $pkg: ${why[$i]}" ;;
    esac
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then sudo="sudo"; else
    echo "deps.sh: need root or sudo to install: ${missing[*]}" >&2; exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
