// gtest main for tests that use Tpetra: MPI and Kokkos must be initialised first.
#include <Tpetra_Core.hpp>
#include <gtest/gtest.h>

int main(int argc, char** argv) {
  Tpetra::ScopeGuard mpi(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
