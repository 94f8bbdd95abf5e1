#!/bin/sh
# Headless OpenGL for `birdsim render`: install Debian's OSMesa (libosmesa6) when we
# are root and apt-get exists; otherwise say that rendering will use EGL.
# Idempotent: prints nothing and changes nothing when OSMesa is already installed.
set -u

have_lib() {  # have_lib SONAME_PREFIX -> 0 when the dynamic loader knows it
    ldconfig -p 2>/dev/null | grep -q "$1" && return 0
    for d in /usr/lib/x86_64-linux-gnu /usr/lib/aarch64-linux-gnu /usr/lib64 /usr/lib /usr/local/lib; do
        ls "$d"/"$1"* >/dev/null 2>&1 && return 0
    done
    return 1
}

if have_lib libOSMesa.so; then
    exit 0
fi

if [ "$(id -u)" = "0" ] && command -v apt-get >/dev/null 2>&1; then
    export DEBIAN_FRONTEND=noninteractive
    if ! apt-get install -y -q --no-install-recommends libosmesa6 >/dev/null 2>&1; then
        apt-get update -q >/dev/null 2>&1
        apt-get install -y -q --no-install-recommends libosmesa6 >/dev/null 2>&1
    fi
    if have_lib libOSMesa.so; then
        echo "setup_gl: installed libosmesa6 (OSMesa); birdsim render uses OSMesa (--gl auto)"
        exit 0
    fi
    echo "setup_gl: apt-get could not install libosmesa6" >&2
fi

if have_lib libEGL.so; then
    echo "setup_gl: OSMesa is not installed (needs root: apt-get install libosmesa6); birdsim render will use EGL"
else
    echo "setup_gl: no headless OpenGL: neither libOSMesa.so nor libEGL.so is installed;" \
         "as root run: apt-get install libosmesa6 (or libegl1 libegl-mesa0)" >&2
fi
exit 0
