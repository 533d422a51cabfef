# ctest driver: `cmake --install` the build tree into a fresh prefix, then import the installed
# Python package (not the build tree's) and solve a spec with it. -D BUILD_DIR, SOURCE_DIR,
# WORK_DIR, PYTHON, SITE_DIR (the package's folder, relative to the prefix).
file(REMOVE_RECURSE "${WORK_DIR}")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${WORK_DIR}/prefix"
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
set(code "import relpos, sys
assert relpos.__file__.startswith(sys.argv[1]), relpos.__file__
r = relpos.solve(sys.argv[2])
assert r['status'] == 'solved' and r['branches'], r
print('installed relpos', relpos.__version__, 'solved', r['name'])")
execute_process(COMMAND ${CMAKE_COMMAND} -E env "PYTHONPATH=${WORK_DIR}/prefix/${SITE_DIR}"
                        ${PYTHON} -c "${code}" "${WORK_DIR}/prefix"
                        "${SOURCE_DIR}/data/scenarios/scenario-d-soda-can-grasp.json"
                WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "the installed package failed (${rc})")
endif()
