# Optional MPI path (-DGPM_MPI=ON; off by default, never needed by make test/report): the
# study runner deals a study's units over the ranks of an mpirun and gathers the rows on rank
# 0 (src/gpm/studies/run/runner.hpp).  Debian: apt-get install libopenmpi-dev openmpi-bin.
option(GPM_MPI "Distribute a study's units over MPI ranks (OpenMPI)" OFF)
if(GPM_MPI)
  find_package(MPI REQUIRED COMPONENTS CXX)
  target_link_libraries(gpm_core PUBLIC MPI::MPI_CXX)
  target_compile_definitions(gpm_core PUBLIC GPM_MPI=1)
  # The data files of 2 ranks are those of 1 process, timing columns aside.
  add_test(NAME mpi_matches_serial
    COMMAND bash ${CMAKE_SOURCE_DIR}/tests/mpi/mpi_matches_serial.sh ${CMAKE_BINARY_DIR})
  set_tests_properties(mpi_matches_serial PROPERTIES TIMEOUT 600)
endif()
