# Every external dependency as an imported target, found the Debian way (tools/setup installs the packages).
#   MPI      Open MPI: particle decomposition, halo exchange, gathers            (MPI::MPI_CXX)
#   PETSc    3.18, pkg-config 'petsc': structure/contact matrices, KSP          (halfeti::petsc)
#   METIS    5: partition of the SPH cell graph and of the structure mesh        (halfeti::metis)
#   HDF5     parallel, pkg-config 'hdf5-openmpi': fields and checkpoints         (halfeti::hdf5)
#   Eigen3   3.4: small dense algebra at points, elements and cables            (Eigen3::Eigen)
#   yaml-cpp scenes                                                              (halfeti::yaml)
#   GTest    tests only                                                          (GTest::gtest)
find_package(MPI REQUIRED COMPONENTS C CXX)
find_package(PkgConfig REQUIRED)
find_package(Eigen3 3.4 REQUIRED NO_MODULE)

pkg_check_modules(PETSC REQUIRED IMPORTED_TARGET petsc)
add_library(halfeti::petsc ALIAS PkgConfig::PETSC)

pkg_check_modules(HDF5MPI REQUIRED IMPORTED_TARGET hdf5-openmpi)
add_library(halfeti::hdf5 ALIAS PkgConfig::HDF5MPI)

pkg_check_modules(YAMLCPP REQUIRED IMPORTED_TARGET yaml-cpp)
add_library(halfeti::yaml ALIAS PkgConfig::YAMLCPP)

find_path(METIS_INCLUDE_DIR metis.h REQUIRED)
find_library(METIS_LIBRARY metis REQUIRED)
add_library(halfeti_metis INTERFACE)
target_include_directories(halfeti_metis SYSTEM INTERFACE ${METIS_INCLUDE_DIR})
target_link_libraries(halfeti_metis INTERFACE ${METIS_LIBRARY})
add_library(halfeti::metis ALIAS halfeti_metis)

if(HALFETI_ENABLE_TESTS)
  find_package(GTest REQUIRED)
endif()
if(HALFETI_ENABLE_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()
