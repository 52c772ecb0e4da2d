# Sourced by the tools that count instructions with valgrind (real_air_trace_cost.sh,
# path_instructions.sh, trace_instructions.sh).  OpenImageIO loads Highway (libhwy), whose start-up
# code times itself with the rdtscp instruction whether or not the processor reports it.  Where
# it does not (some virtual machines), valgrind refuses the instruction and every mirage program
# dies with SIGILL before main.  valgrind_env PROGRAM DIR then puts into DIR a copy of libhwy
# with each rdtscp (0f 01 f9) replaced by rdtsc; nop (0f 31 90), which reads the same counter,
# and exports LD_LIBRARY_PATH so that the programs run under valgrind load that copy.  The
# system's library is not touched, and nothing changes where valgrind runs them as they are.
#
#   . tools/valgrind_env.sh; valgrind_env build/mirage "$tmp"
refuses_instruction() {  # PROGRAM: whether valgrind stops it at an illegal instruction
    # (in a shell of its own, which reports the kill to its own, discarded, standard error)
    sh -c 'valgrind --tool=none "$1" --version 2>&1 >/dev/null </dev/null; true' sh "$1" \
        2>/dev/null | grep -q "SIGILL"
}

valgrind_env() {  # PROGRAM DIR
    refuses_instruction "$1" || return 0
    hwy=$(ldd "$1" | awk '/libhwy\.so/ { print $3; exit }')
    if [ -z "$hwy" ] || ! command -v python3 >/dev/null; then
        echo "valgrind cannot run $1 (and no libhwy to mend)" >&2
        return 1
    fi
    mkdir -p "$2/valgrind-libs"
    python3 - "$hwy" "$2/valgrind-libs/$(basename "$hwy")" <<'EOF'
import sys
data = open(sys.argv[1], 'rb').read()
open(sys.argv[2], 'wb').write(data.replace(b'\x0f\x01\xf9', b'\x0f\x31\x90'))
EOF
    LD_LIBRARY_PATH="$2/valgrind-libs${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
    export LD_LIBRARY_PATH
    if refuses_instruction "$1"; then
        echo "valgrind cannot run $1, even with libhwy's rdtscp replaced" >&2
        return 1
    fi
    echo "(valgrind: libhwy's rdtscp replaced by rdtsc in a copy, $2/valgrind-libs)" >&2
}
