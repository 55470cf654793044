#!/bin/sh
# Installs what the build needs when it is missing, idempotently and loudly.
# Usage: scripts/deps.sh cmocka|box2d|chipmunk|fuzz ...
# As root with apt: installs the Debian package (running apt-get update once if
# the package is unknown). Otherwise: stops with a message naming the package.
set -u

have_pkgconfig() { pkg-config --exists "$1" 2>/dev/null; }
have_header() { [ -f "/usr/include/$1" ]; }

updated=0
apt_install() {
    pkg=$1
    if [ "$(id -u)" != "0" ] || ! command -v apt-get >/dev/null 2>&1; then
        echo "sepax: missing dependency: install the Debian package '$pkg' (apt-get install $pkg)" >&2
        exit 1
    fi
    echo "sepax: installing missing Debian package '$pkg'" >&2
    if [ "$updated" = 0 ] && ! apt-cache show "$pkg" >/dev/null 2>&1; then
        apt-get update -q >&2 || true
        updated=1
    fi
    if ! DEBIAN_FRONTEND=noninteractive apt-get install -y -q "$pkg" >&2; then
        if [ "$updated" = 0 ]; then
            apt-get update -q >&2 || true
            updated=1
            DEBIAN_FRONTEND=noninteractive apt-get install -y -q "$pkg" >&2 && return 0
        fi
        echo "sepax: could not install '$pkg'" >&2
        exit 1
    fi
}

for dep in "$@"; do
    case "$dep" in
    cmocka) have_pkgconfig cmocka || apt_install libcmocka-dev ;;
    box2d) have_header box2d/box2d.h || apt_install libbox2d-dev ;;
    chipmunk) have_header chipmunk/chipmunk.h || apt_install libchipmunk-dev ;;
    fuzz) # clang and its libFuzzer + sanitizer runtimes (make fuzz)
        command -v clang >/dev/null 2>&1 || apt_install clang
        ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-*.a >/dev/null 2>&1 ||
            apt_install libclang-rt-14-dev ;;
    *) echo "sepax: deps.sh: unknown dependency '$dep'" >&2; exit 2 ;;
    esac
done
exit 0
