# Out-of-range options and scene keys end at once with the key, the value and
# the range (run by CTest as a script, with a timeout: each of these used to run
# for minutes):
#   cmake -DAMLS=<amls> -DSCENE=<clover2d.json> -DWORK_DIR=<dir> -P parameter_checks_test.cmake
include("${CMAKE_CURRENT_LIST_DIR}/amls_command_checks.cmake")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(out "${WORK_DIR}/out")

set(range "must be within [1.5, 32] (the influence radius Delta in units of h), got 3e-06")
amls_fails("--radius-factor: ${range}" "${out}.json" vortex --grid 128 --radius-factor 0.000003 --json "${out}.json")
amls_fails("--radius-factor: ${range}" "${out}.ply" resample "${SCENE}" --radius-factor 0.000003 --out "${out}.ply")

# The clover2d scene with the same radius factor.
file(READ "${SCENE}" scene)
string(JSON scene SET "${scene}" radius_factor "3e-06")
file(WRITE "${WORK_DIR}/tiny_radius.json" "${scene}")
amls_fails("tiny_radius.json: radius_factor: ${range}" "${out}.json" deform "${WORK_DIR}/tiny_radius.json" --json "${out}.json")

# A mesh whose one vertex has a typo (07363029 for 0.7363029), sampled at the spacing meant for it.
file(WRITE "${WORK_DIR}/typo.obj"
  "v 0.2 0.2 0.2\nv 0.8 0.2 0.2\nv 0.8 0.8 0.2\nv 0.2 0.8 0.2\nv 0.2 0.2 0.8\nv 0.8 0.2 0.8\n"
  "v 07363029 0.255480 0.607000\nv 0.2 0.8 0.8\n"
  "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n")
amls_fails("typo.obj: mesh sampling: spacing 0.015625 would make about 4.44123e+17 samples, more than 2e+07"
           "${out}.ply" resample "${WORK_DIR}/typo.obj" --spacing 0.015625 --out "${out}.ply")

# Other options, one of each kind.
amls_fails("--grid: must be within [8, 65536] (cells per unit length), got 4" "${out}.json" vortex --grid 4 --json "${out}.json")
amls_fails("--grid 65536 would start from" "${out}.json" enright --grid 65536 --json "${out}.json")
amls_fails("--dt: must be within [0.0001, 1] (time between resamplings), got nan" "${out}.json" vortex --dt nan --json "${out}.json")
amls_fails("--threads: must be within [1, 256] (threads), got 100000" "${out}.json" vortex --threads 100000 --json "${out}.json")
amls_fails("--tracers: must be within [1, 1000]" "${out}.json" deform "${SCENE}" --tracers 5000 --json "${out}.json")
amls_fails("--size: expected WIDTHxHEIGHT with each side a whole number within [1, 16384] pixels" "${out}.png"
           render "${SCENE}" --size 20000x10 --out "${out}.png")
