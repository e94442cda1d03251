#include "validation/studies/relative_error.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "core/error.h"

namespace verity::studies {

namespace {

const std::vector<float>& plane(const ImageChannels& image, const std::string& name) {
  const auto it = image.planes.find(name);
  if (it == image.planes.end())
    throw std::logic_error("a reference without a channel \"" + name + "\" (readReference)");
  return it->second;
}

void checkSize(const Film& film, const ImageChannels& reference) {
  if (film.width() != reference.width || film.height() != reference.height)
    throw std::logic_error(fmt::format("an image of {}×{} against a reference of {}×{}",
                                       film.width(), film.height(), reference.width,
                                       reference.height));
}

}  // namespace

ImageChannels readReference(const std::filesystem::path& file) {
  ImageChannels image = readExr(file);
  for (const char* name : {"R", "G", "B"})
    if (!image.planes.count(name))
      throw VerityError(
          file.string(), "",
          fmt::format("a reference image needs channels R, G and B; it has no {}", name));
  return image;
}

ErrorStats compareToReference(const Film& film, const ImageChannels& reference) {
  checkSize(film, reference);
  const std::vector<float>* ref[3] = {&plane(reference, "R"), &plane(reference, "G"),
                                      &plane(reference, "B")};
  ErrorStats s;
  double sumRel = 0, sumVar = 0, sumRelVar = 0;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      const size_t i = size_t(y) * film.width() + x;
      const uint32_t n = film.count(x, y);
      const Color3 mean = film.mean(x, y);
      const Color3 var = film.sampleVariance(x, y);
      bool finite = n > 0;
      for (int c = 0; c < 3; ++c) finite = finite && std::isfinite((*ref[c])[i]);
      if (!finite) continue;
      for (int c = 0; c < 3; ++c) {
        const double r = (*ref[c])[i];
        const double varOfMean = double(var[c]) / n;
        sumRel += relativeSquaredError(mean[c], r);
        sumVar += varOfMean;
        sumRelVar += varOfMean / (r * r + kRelEpsilon);
      }
      ++s.pixelsUsed;
    }
  if (s.pixelsUsed == 0) return s;
  const double terms = 3.0 * double(s.pixelsUsed);
  s.relMse = sumRel / terms;
  s.meanVariance = sumVar / terms;
  s.relVariance = sumRelVar / terms;
  return s;
}

double imageRelMse(const ImageChannels& image, const std::array<std::string, 3>& rgb,
                   const ImageChannels& reference, const std::string& file) {
  if (image.width != reference.width || image.height != reference.height)
    throw VerityError(file, "",
                      fmt::format("an image of {}×{} against a reference of {}×{}", image.width,
                                  image.height, reference.width, reference.height));
  const std::vector<float>* ref[3] = {&plane(reference, "R"), &plane(reference, "G"),
                                      &plane(reference, "B")};
  const std::vector<float>* x[3] = {&plane(image, rgb[0]), &plane(image, rgb[1]),
                                    &plane(image, rgb[2])};
  double sum = 0;
  size_t terms = 0;
  for (size_t i = 0; i < ref[0]->size(); ++i) {
    bool finite = true;
    for (int c = 0; c < 3; ++c) finite = finite && std::isfinite((*ref[c])[i]);
    if (!finite) continue;
    for (int c = 0; c < 3; ++c) {
      if (!std::isfinite((*x[c])[i]))
        throw VerityError(file, "",
                          fmt::format("pixel ({}, {}) of channel {} is {}", i % image.width,
                                      i / image.width, rgb[c], (*x[c])[i]));
      sum += relativeSquaredError((*x[c])[i], (*ref[c])[i]);
      ++terms;
    }
  }
  if (terms == 0) throw VerityError(file, "", "the reference has no finite pixel");
  return sum / double(terms);
}

FireflyShare fireflyShare(const Film& film, const ImageChannels& reference, double k) {
  checkSize(film, reference);
  if (!film.tracksMaxima())
    throw std::logic_error("fireflies need the film's per-pixel maxima (Film::trackMaxima)");
  const std::vector<float>* ref[3] = {&plane(reference, "R"), &plane(reference, "G"),
                                      &plane(reference, "B")};
  FireflyShare s;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      const size_t i = size_t(y) * film.width() + x;
      const uint32_t n = film.count(x, y);
      bool finite = n > 0;
      for (int c = 0; c < 3; ++c) finite = finite && std::isfinite((*ref[c])[i]);
      if (!finite) continue;
      const Color3 mean = film.mean(x, y), largest = film.maxSample(x, y);
      double error = 0;
      bool far = false;
      for (int c = 0; c < 3; ++c) {
        const double r = (*ref[c])[i];
        const double scale = std::sqrt(r * r + kRelEpsilon);
        error += relativeSquaredError(mean[c], r);
        far = far || (double(largest[c]) - r) / n > k * scale;
      }
      s.allRelMseSum += error;
      if (far) {
        ++s.pixels;
        s.relMseSum += error;
      }
    }
  return s;
}

std::vector<float> relativeErrorImage(const Film& film, const ImageChannels& reference) {
  checkSize(film, reference);
  const std::vector<float>* ref[3] = {&plane(reference, "R"), &plane(reference, "G"),
                                      &plane(reference, "B")};
  std::vector<float> out(size_t(film.width()) * film.height());
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      const size_t i = size_t(y) * film.width() + x;
      const Color3 mean = film.mean(x, y);
      double sum = 0;
      for (int c = 0; c < 3; ++c) sum += relativeSquaredError(mean[c], (*ref[c])[i]);
      out[i] = float(std::sqrt(sum / 3));
    }
  return out;
}

double referenceRelMse(const ImageChannels& reference) {
  const std::vector<float>& samples = plane(reference, "samples");
  double sum = 0;
  size_t terms = 0;
  for (const char* c : {"R", "G", "B"}) {
    const std::vector<float>& mean = plane(reference, c);
    const std::vector<float>& var = plane(reference, std::string("variance.") + c);
    for (size_t i = 0; i < mean.size(); ++i) {
      if (!(samples[i] > 0) || !std::isfinite(mean[i]) || !std::isfinite(var[i])) continue;
      sum += double(var[i]) / samples[i] / (double(mean[i]) * mean[i] + kRelEpsilon);
      ++terms;
    }
  }
  return terms ? sum / double(terms) : 0;
}

}  // namespace verity::studies
