#include "distributed/film_transfer.h"

#include <climits>

#include "core/error.h"

namespace verity {

namespace {
constexpr int kFilmTag = 18;
// A film's sums are sent as one array of doubles.
static_assert(sizeof(Eigen::Array3d) == 3 * sizeof(double));

int elementCount(size_t n) {
  if (n > size_t(INT_MAX))
    throw VerityError("", "camera.resolution",
                      "the image is too large to send between MPI ranks in one message");
  return int(n);
}
}  // namespace

void FilmSender::send(int rank, int chunk, int passes, Film& film) {
  wait();
  header_ = {chunk, passes};
  const int values = elementCount(film.sums().size() * 3);
  const int pixels = elementCount(film.counts().size());
  requests_.resize(5);
  // Messages between two ranks with one tag arrive in the order they were sent.
  MPI_Isend(header_.data(), 2, MPI_INT, rank, kFilmTag, MPI_COMM_WORLD, &requests_[0]);
  MPI_Isend(film.sums().data()->data(), values, MPI_DOUBLE, rank, kFilmTag, MPI_COMM_WORLD,
            &requests_[1]);
  MPI_Isend(film.sumSquares().data()->data(), values, MPI_DOUBLE, rank, kFilmTag, MPI_COMM_WORLD,
            &requests_[2]);
  MPI_Isend(film.counts().data(), pixels, MPI_UINT32_T, rank, kFilmTag, MPI_COMM_WORLD,
            &requests_[3]);
  MPI_Isend(film.invalidCounts().data(), pixels, MPI_UINT32_T, rank, kFilmTag, MPI_COMM_WORLD,
            &requests_[4]);
}

void FilmSender::wait() {
  if (requests_.empty()) return;
  MPI_Waitall(int(requests_.size()), requests_.data(), MPI_STATUSES_IGNORE);
  requests_.clear();
}

ReceivedChunk receiveFilm(int rank, Film& film) {
  std::array<int, 2> header{};
  const int values = elementCount(film.sums().size() * 3);
  const int pixels = elementCount(film.counts().size());
  MPI_Recv(header.data(), 2, MPI_INT, rank, kFilmTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  MPI_Recv(film.sums().data()->data(), values, MPI_DOUBLE, rank, kFilmTag, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  MPI_Recv(film.sumSquares().data()->data(), values, MPI_DOUBLE, rank, kFilmTag, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  MPI_Recv(film.counts().data(), pixels, MPI_UINT32_T, rank, kFilmTag, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  MPI_Recv(film.invalidCounts().data(), pixels, MPI_UINT32_T, rank, kFilmTag, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return {header[0], header[1]};
}

}  // namespace verity
