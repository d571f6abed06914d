#include "sweeps/mpi_cluster.hpp"

#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "common/input_error.hpp"

namespace crux {

namespace {

constexpr int kRequestTag = 1, kOrderTag = 2;

class MpiCoordinatorLink final : public CoordinatorLink {
 public:
  explicit MpiCoordinatorLink(std::size_t slots) : slots_(slots) {}
  std::size_t slots() const override { return slots_; }
  void poll(std::vector<Request>& requests) override {
    for (;;) {
      int arrived = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, kRequestTag, MPI_COMM_WORLD, &arrived, &status);
      if (!arrived) return;
      long long finished = -1;
      MPI_Recv(&finished, 1, MPI_LONG_LONG, status.MPI_SOURCE, kRequestTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      requests.push_back({status.MPI_SOURCE, finished});
    }
  }
  void assign(int worker, std::size_t task) override { send(worker, static_cast<long long>(task)); }
  void stop(int worker) override { send(worker, -1); }

 private:
  static void send(int worker, long long order) {
    MPI_Send(&order, 1, MPI_LONG_LONG, worker, kOrderTag, MPI_COMM_WORLD);
  }
  std::size_t slots_;
};

class MpiWorkerLink final : public WorkerLink {
 public:
  void request(long long finished) override { MPI_Send(&finished, 1, MPI_LONG_LONG, 0, kRequestTag, MPI_COMM_WORLD); }
  void poll(std::vector<long long>& orders) override {
    for (;;) {
      int arrived = 0;
      MPI_Iprobe(0, kOrderTag, MPI_COMM_WORLD, &arrived, MPI_STATUS_IGNORE);
      if (!arrived) return;
      long long order = -1;
      MPI_Recv(&order, 1, MPI_LONG_LONG, 0, kOrderTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      orders.push_back(order);
    }
  }
};

int environment_int(const char* name, int fallback) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0' ? std::atoi(value) : fallback;
}

}  // namespace

bool launched_by_mpi() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMIX_RANK") != nullptr ||
         std::getenv("PMI_SIZE") != nullptr;
}

int local_processes() { return std::max(1, environment_int("OMPI_COMM_WORLD_LOCAL_SIZE", 1)); }

MpiCluster::MpiCluster(int* argc, char*** argv) {
  int provided = 0;
  MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
  if (provided < MPI_THREAD_FUNNELED) {
    MPI_Finalize();
    throw std::runtime_error("MPI does not support threads that leave MPI calls to the main thread");
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiCluster::~MpiCluster() { MPI_Finalize(); }

bool MpiCluster::share_readiness(bool ready) {
  int value = ready ? 1 : 0;
  MPI_Bcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return value == 1;
}

void MpiCluster::barrier() { MPI_Barrier(MPI_COMM_WORLD); }

std::unique_ptr<CoordinatorLink> MpiCluster::coordinator_link() {
  std::vector<int> slots(static_cast<std::size_t>(size_));
  int mine = 0;
  MPI_Gather(&mine, 1, MPI_INT, slots.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::size_t total = 0;
  for (const int s : slots) total += static_cast<std::size_t>(s);
  return std::make_unique<MpiCoordinatorLink>(total);
}

std::unique_ptr<WorkerLink> MpiCluster::worker_link(int threads) {
  MPI_Gather(&threads, 1, MPI_INT, nullptr, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return std::make_unique<MpiWorkerLink>();
}

SweepCluster::Agreement MpiCluster::agree(bool ok, std::uint64_t job) {
  int mine = ok ? 1 : 0, every = 0, coordinator = mine;
  MPI_Allreduce(&mine, &every, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  MPI_Bcast(&coordinator, 1, MPI_INT, 0, MPI_COMM_WORLD);
  unsigned long long low = job, high = job;
  MPI_Allreduce(MPI_IN_PLACE, &low, 1, MPI_UNSIGNED_LONG_LONG, MPI_MIN, MPI_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, &high, 1, MPI_UNSIGNED_LONG_LONG, MPI_MAX, MPI_COMM_WORLD);
  return {every == 1, coordinator == 1, low == high};
}

void MpiCluster::fail(const std::exception& failure) {
  std::fprintf(stderr, "crux: %s\n", failure.what());
  std::fflush(stderr);
  MPI_Abort(MPI_COMM_WORLD, dynamic_cast<const InputError*>(&failure) != nullptr ? 2 : 1);
  std::abort();
}

}  // namespace crux
