#!/bin/sh
# A headless browser for the studio's browser tests (tests/test_studio_browser.py): Debian's
# chromium, installed when we are root and apt-get exists (Playwright drives it through its
# executable path; Playwright's own browser download is never used). Idempotent: prints
# nothing and changes nothing when /usr/bin/chromium is already there. Without it the
# browser tests skip with the reason.
set -u
CHROMIUM=/usr/bin/chromium

if [ -x "$CHROMIUM" ]; then
    exit 0
fi
if [ "$(id -u)" = "0" ] && command -v apt-get >/dev/null 2>&1; then
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -q >/dev/null 2>&1
    if apt-get install -y -q --no-install-recommends chromium >/dev/null 2>&1 && [ -x "$CHROMIUM" ]; then
        echo "setup_browser: installed Debian's chromium ($CHROMIUM) for the browser tests"
        exit 0
    fi
    echo "setup_browser: apt-get could not install chromium; the browser tests will skip" >&2
else
    echo "setup_browser: chromium is not installed (needs root: apt-get install chromium); the browser tests will skip"
fi
exit 0
