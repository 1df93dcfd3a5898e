# libFuzzer targets, one per reader (tests/fuzz/fuzz_<name>.cpp), built with
# -DINSMC_FUZZ=ON by clang with -fsanitize=fuzzer,address,undefined. They
# link the readers (insmc_readers, the study's files in insmc_montecarlo),
# the option parser (insmc_options) and the commands that write records
# (insmc_record_commands: import-imu, simulate): `cmake --build DIR --target
# fuzz_records ...` builds those and not the program.
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "INSMC_FUZZ needs clang (libFuzzer): -DCMAKE_CXX_COMPILER=clang++")
endif()
add_library(insmc_fuzz_entry STATIC ${CMAKE_CURRENT_LIST_DIR}/fuzz_entry.cpp)
target_link_libraries(insmc_fuzz_entry PUBLIC insmc_record_commands insmc_options insmc_montecarlo)
set(INSMC_FUZZ_TARGETS records imu bounds config checkpoint quantity run_json options import_imu simulate)
foreach(name ${INSMC_FUZZ_TARGETS})
  add_executable(fuzz_${name} ${CMAKE_CURRENT_LIST_DIR}/fuzz_${name}.cpp)
  target_link_libraries(fuzz_${name} PRIVATE insmc_fuzz_entry)
  target_link_options(fuzz_${name} PRIVATE -fsanitize=fuzzer)
endforeach()
