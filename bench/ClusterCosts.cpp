// ClusterCosts: the measured costs behind bench/README.md's model of evolution over MPI ranks
// (issue 30). Run as `mpirun -n 2 ClusterCosts`; rank 0 prints
//  1. the round trip of a small message (a chunk's request and reply, 32 bytes) between two
//     ranks, blocking calls, mean over 20000 trips;
//  2. the broadcast of a population of 35-8-5 networks (n = 333 doubles each) for 1,000 and
//     10,000 genomes: seconds and bytes a second;
//  3. the leader's serial work a generation: CMA-ES ask + tell at n = 333 for populations of
//     100, 1,000 and 10,000, and the same for the self-adaptive ES (no covariance), in CPU time
//     (the process's: it is single-threaded), so that a loaded machine measures the work and not
//     its share of the processor.

#include <Evolution/CmaEs.h>
#include <Evolution/SelfAdaptiveEs.h>

#include <mpi.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <ctime>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

double roundTrip(int rank, int trips) {
  double message[4] = {1, 2, 3, 4};
  MPI_Barrier(MPI_COMM_WORLD);
  const auto start = Clock::now();
  for (int i = 0; i < trips; ++i) {
    if (rank == 0) {
      MPI_Send(message, 4, MPI_DOUBLE, 1, 0, MPI_COMM_WORLD);
      MPI_Recv(message, 4, MPI_DOUBLE, 1, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    } else if (rank == 1) {
      MPI_Recv(message, 4, MPI_DOUBLE, 0, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      MPI_Send(message, 4, MPI_DOUBLE, 0, 0, MPI_COMM_WORLD);
    }
  }
  return seconds(start) / trips;
}

double broadcast(std::size_t doubles, int repeats) {
  std::vector<double> data(doubles, 0.5);
  MPI_Barrier(MPI_COMM_WORLD);
  const auto start = Clock::now();
  for (int i = 0; i < repeats; ++i)
    MPI_Bcast(data.data(), static_cast<int>(doubles), MPI_DOUBLE, 0, MPI_COMM_WORLD);
  MPI_Barrier(MPI_COMM_WORLD);
  return seconds(start) / repeats;
}

double askTell(thyrix::Strategy& strategy, int generations) {
  const std::size_t population = strategy.populationSize();
  std::vector<double> fitness(population);
  const std::clock_t start = std::clock();
  for (int g = 0; g < generations; ++g) {
    const auto points = strategy.ask();
    for (std::size_t i = 0; i < population; ++i) fitness[i] = -points[i][0] * points[i][0];
    strategy.tell(fitness);
  }
  return static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC / generations;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0;
  int size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size >= 2) {
    roundTrip(rank, 1000);  // warm-up
    const double trip = roundTrip(rank, 20000);
    if (rank == 0) std::printf("round trip of 32 bytes: %.2f us\n", trip * 1e6);
    for (std::size_t population : {1000u, 10000u}) {
      const std::size_t doubles = population * 333;
      const double time = broadcast(doubles, 5);
      if (rank == 0)
        std::printf("broadcast of %zu genomes (%.1f MB) to %d ranks: %.2f ms, %.2f GB/s\n",
                    population, static_cast<double>(doubles) * 8e-6, size, time * 1e3,
                    static_cast<double>(doubles) * 8 / time * 1e-9);
    }
  }
  if (rank == 0) {
    for (std::size_t population : {100u, 1000u, 10000u}) {
      const int generations = population >= 10000 ? 3 : 20;
      thyrix::CmaEs cma(std::vector<double>(333, 0.0), 0.5, population, 1);
      thyrix::SelfAdaptiveEs sa(std::vector<double>(333, 0.0), 0.5, population, 0, 1);
      const double cmaTime = askTell(cma, generations);
      const double saTime = askTell(sa, generations);
      std::printf("ask + tell, n = 333, population %zu: CMA-ES %.2f ms, SA-ES %.2f ms of CPU\n",
                  population, cmaTime * 1e3, saTime * 1e3);
    }
  }
  MPI_Finalize();
  return 0;
}
