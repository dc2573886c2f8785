#!/bin/bash
# dpana on DPANA_NP ranks: $DPANA_MPIEXEC -np $DPANA_NP $DPANA "$@" (the
# variables set by tests/CMakeLists.txt), so that tests/prm/run_prm_test.sh
# runs its bad-input checks on the MPI route.
exec $DPANA_MPIEXEC -np "$DPANA_NP" "$DPANA" "$@"
