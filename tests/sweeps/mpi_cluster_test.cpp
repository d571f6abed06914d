// MpiCluster itself runs only under mpirun: CliSweep.TwoMpiRanksWriteTheSingleProcessBytes
// runs crux sweep there. Here: how a process knows it was launched by MPI.
#include "sweeps/mpi_cluster.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

namespace crux {
namespace {

TEST(MpiCluster, ALaunchIsKnownByTheLaunchersVariables) {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "OMPI_COMM_WORLD_LOCAL_SIZE"}) {
    ::unsetenv(name);
  }
  EXPECT_FALSE(launched_by_mpi());
  EXPECT_EQ(local_processes(), 1);
  ::setenv("OMPI_COMM_WORLD_SIZE", "4", 1);
  ::setenv("OMPI_COMM_WORLD_LOCAL_SIZE", "2", 1);
  EXPECT_TRUE(launched_by_mpi());
  EXPECT_EQ(local_processes(), 2);
  ::unsetenv("OMPI_COMM_WORLD_SIZE");
  ::unsetenv("OMPI_COMM_WORLD_LOCAL_SIZE");
  ::setenv("PMIX_RANK", "0", 1);
  EXPECT_TRUE(launched_by_mpi());
  ::unsetenv("PMIX_RANK");
}

}  // namespace
}  // namespace crux
