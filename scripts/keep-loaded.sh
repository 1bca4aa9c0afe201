#!/usr/bin/env bash
# Builds OUT.so, a library whose dlclose does nothing, for LD_PRELOAD under the sanitizers: the process then
# keeps the GL driver mapped to the end, where a sanitizer loses track of it once it is unloaded
# (LeakSanitizer reports its objects as leaks from no known module; ThreadSanitizer stops a process that
# unloads a library its suppressions name).
# Usage: scripts/keep-loaded.sh OUT.so
set -euo pipefail
echo 'int dlclose(void* handle) { (void)handle; return 0; }' | cc -shared -fPIC -x c -o "$1" -
