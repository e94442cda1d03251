// Moving a chunk's film between the ranks of a job: a header (chunk index, passes it holds)
// and the film's four accumulators (sums, sums of squares, counts, invalid counts), so the
// receiver adds exactly the numbers the sender summed.
#pragma once

#include <mpi.h>

#include <array>
#include <vector>

#include "film/film.h"

namespace verity {

// Sends without blocking, so that the sender renders its next chunk while this one travels.
class FilmSender {
 public:
  FilmSender() = default;
  FilmSender(const FilmSender&) = delete;
  FilmSender& operator=(const FilmSender&) = delete;
  ~FilmSender() { wait(); }

  // Starts sending `film` to `rank`; the film must not change until wait() returns.
  void send(int rank, int chunk, int passes, Film& film);
  // Completes the send in flight, if any.
  void wait();

 private:
  std::array<int, 2> header_{};
  std::vector<MPI_Request> requests_;
};

struct ReceivedChunk {
  int chunk = 0, passes = 0;
};
// Receives the next film `rank` sends into `film` (same resolution) and says what it holds.
ReceivedChunk receiveFilm(int rank, Film& film);

}  // namespace verity
