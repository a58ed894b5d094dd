#include "mpi_session.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <vector>

// The C API only: OpenMPI's deprecated C++ bindings would need libmpi_cxx.
#define OMPI_SKIP_MPICXX 1
#define MPICH_SKIP_MPICXX 1
#include <mpi.h>

namespace rsi {
namespace {

enum Tag { task_tag = 1, done_tag = 2, fatal_tag = 3 };

/// OpenMPI's mpirun sets OMPI_COMM_WORLD_SIZE; Slurm's srun (PMIx or PMI2)
/// sets PMIX_RANK or PMI_RANK.
bool started_by_launcher() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK"})
    if (std::getenv(name) != nullptr) return true;
  return false;
}

void check(int status, const char* call) {
  if (status != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + call + " failed");
}

} // namespace

MpiSession::MpiSession() {
  if (!started_by_launcher()) return;
  int provided = 0;
  check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
  m_initialised = true;
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  check(MPI_Comm_rank(MPI_COMM_WORLD, &m_rank), "MPI_Comm_rank");
  check(MPI_Comm_size(MPI_COMM_WORLD, &m_size), "MPI_Comm_size");
  if (m_rank != 0) {
    if (std::freopen("/dev/null", "w", stdout) == nullptr ||
        std::freopen("/dev/null", "w", stderr) == nullptr)
      throw std::runtime_error("MPI rank: cannot silence stdout and stderr");
  }
}

MpiSession::~MpiSession() {
  if (!m_initialised) return;
  // Rank 0 leaving by an exception (a signal, bad input, a failed write):
  // MPI_Finalize would wait for the other ranks' runs, or forever for a
  // rank that was killed, and mpirun would SIGKILL rank 0 before it says
  // why. Leaving without it, rank 0 prints its line and exits; mpirun then
  // ends the other ranks (and says so).
  if (m_rank == 0 && std::uncaught_exceptions() > 0) return;
  MPI_Finalize();
}

void MpiSession::send_task(int task, double seconds, const std::string& row) const {
  // task index and wall time as text before the row: one message, no packing.
  char head[64];
  const int n = std::snprintf(head, sizeof head, "%d %.17g\n", task, seconds);
  const std::string message = std::string(head, static_cast<size_t>(n)) + row;
  check(MPI_Send(message.data(), static_cast<int>(message.size()), MPI_CHAR, 0, task_tag,
                 MPI_COMM_WORLD),
        "MPI_Send");
}

void MpiSession::send_done() const {
  check(MPI_Send(nullptr, 0, MPI_CHAR, 0, done_tag, MPI_COMM_WORLD), "MPI_Send");
}

void MpiSession::send_fatal(const std::string& what) const {
  check(MPI_Send(what.data(), static_cast<int>(what.size()), MPI_CHAR, 0, fatal_tag,
                 MPI_COMM_WORLD),
        "MPI_Send");
}

void MpiSession::end_reported(const std::string& what) {
  send_fatal(what);
  if (m_initialised) MPI_Finalize();
  m_initialised = false;
  std::fflush(nullptr);
  std::_Exit(0);
}

bool MpiSession::poll(RankMessage& message) const {
  if (!m_initialised) return false;
  int flag = 0;
  MPI_Status status;
  check(MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status), "MPI_Iprobe");
  if (!flag) return false;
  int count = 0;
  check(MPI_Get_count(&status, MPI_CHAR, &count), "MPI_Get_count");
  std::vector<char> buffer(static_cast<size_t>(count) + 1, '\0');
  check(MPI_Recv(buffer.data(), count, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG,
                 MPI_COMM_WORLD, MPI_STATUS_IGNORE),
        "MPI_Recv");
  message = RankMessage{};
  message.rank = status.MPI_SOURCE;
  const std::string text(buffer.data(), static_cast<size_t>(count));
  if (status.MPI_TAG == done_tag) {
    message.kind = RankMessage::Kind::done;
  } else if (status.MPI_TAG == fatal_tag) {
    message.kind = RankMessage::Kind::fatal;
    message.text = text;
  } else {
    const size_t line = text.find('\n');
    if (line == std::string::npos ||
        std::sscanf(text.c_str(), "%d %lf", &message.task, &message.seconds) != 2)
      throw std::runtime_error("MPI: a malformed task message from rank " +
                               std::to_string(message.rank));
    message.kind = RankMessage::Kind::task;
    message.text = text.substr(line + 1);
  }
  return true;
}

} // namespace rsi
