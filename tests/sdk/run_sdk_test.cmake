# ctest driver: install the SDK from the build tree, then configure, build and run an
# out-of-tree plugin project against it. -D BUILD_DIR, SOURCE_DIR, WORK_DIR.
file(REMOVE_RECURSE "${WORK_DIR}")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${WORK_DIR}/prefix"
                RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S "${SOURCE_DIR}/tests/sdk" -B "${WORK_DIR}/build"
                        -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DRELPOS_SOURCE_DIR=${SOURCE_DIR}
                        -DCMAKE_BUILD_TYPE=Release
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "configuring the out-of-tree plugin project failed (${rc})")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build "${WORK_DIR}/build" -j 2 RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building the out-of-tree plugins failed (${rc})")
endif()
execute_process(COMMAND "${WORK_DIR}/build/sdk_check" RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "the conformance kits failed on the out-of-tree plugins (${rc})")
endif()
execute_process(COMMAND "${WORK_DIR}/build/collision_check" RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "collision filtering through the installed SDK failed (${rc})")
endif()
# The installed command finds the installed example plugins by name.
execute_process(COMMAND "${WORK_DIR}/prefix/bin/relpos" rules --plugin helical
                OUTPUT_VARIABLE rules RESULT_VARIABLE rc)
if(rc OR NOT rules MATCHES "prefix/lib/relpos/plugins/relpos-helical.so")
  message(FATAL_ERROR "the installed relpos did not find the installed plugin 'helical' (${rc})")
endif()
