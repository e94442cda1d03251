#include "compare_binding.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>

#include "validation/compare/compare_decision.h"
#include "validation/compare/distinct_files.h"
#include "validation/compare/render_set_side.h"
#include "validation/compare/side_loading.h"

namespace verity::python {

namespace py = pybind11;
using validation::CompareDecision;
using validation::kChannelNames;
using validation::kChannels;
using validation::TileTest;

namespace {

std::string shapeText(const py::array& image) {
  std::vector<py::ssize_t> shape(image.shape(), image.shape() + image.ndim());
  return fmt::format("({})", fmt::join(shape, ", "));
}

// One side's renders as ImageChannels (planes R, G and B, row-major), named "a[0]", "a[1]",
// ...: a sequence of (H, W, 3) float arrays or one (N, H, W, 3) array. Every render must have
// the shape of `reference` (the other side's first) when it is given.
std::pair<std::vector<std::string>, std::vector<ImageChannels>> renders(const py::object& side,
                                                                        const std::string& name,
                                                                        const py::array* reference,
                                                                        py::array* first) {
  if (py::isinstance<py::str>(side) || !py::isinstance<py::sequence>(side))
    throw py::type_error(
        fmt::format("verity.compare: {} must be a sequence of (H, W, 3) arrays, an (N, H, W, 3) "
                    "array or a sequence of file names",
                    name));
  if (py::isinstance<py::array>(side) && py::array(side).ndim() != 4)
    throw py::value_error(
        fmt::format("verity.compare: {} has shape {}; give a sequence of (H, W, 3) renders or an "
                    "(N, H, W, 3) array",
                    name, shapeText(py::array(side))));
  const py::sequence items = py::reinterpret_borrow<py::sequence>(side);
  if (py::len(items) < size_t(validation::RenderSetSide::kMinimumRenders))
    throw py::value_error(fmt::format(
        "verity.compare: {} has {} render(s); a set needs at least {} (its variance comes from "
        "the spread of independent renders)",
        name, py::len(items), validation::RenderSetSide::kMinimumRenders));
  std::vector<std::string> labels;
  std::vector<ImageChannels> images;
  for (size_t r = 0; r < py::len(items); ++r) {
    const std::string label = fmt::format("{}[{}]", name, r);
    const py::array image = py::array::ensure(items[r]);
    if (!image || image.dtype().kind() != 'f' || (image.itemsize() != 4 && image.itemsize() != 8))
      throw py::value_error(fmt::format(
          "verity.compare: {} must be a float32 or float64 array{}", label,
          image ? ", not " + py::str(image.dtype()).cast<std::string>() : std::string()));
    if (image.ndim() != 3 || image.shape(2) != 3)
      throw py::value_error(
          fmt::format("verity.compare: {} has shape {}; each render must be (H, W, 3)", label,
                      shapeText(image)));
    const py::array* against = r > 0 ? first : reference;
    if (against && (image.shape(0) != against->shape(0) || image.shape(1) != against->shape(1)))
      throw py::value_error(fmt::format("verity.compare: {} has shape {}, while {} has {}", label,
                                        shapeText(image), r > 0 ? name + "[0]" : "a[0]",
                                        shapeText(*against)));
    if (r == 0) *first = image;
    // As float32, what an EXR render holds.
    const auto pixels = py::array_t<float, py::array::c_style | py::array::forcecast>(image);
    const auto view = pixels.unchecked<3>();
    ImageChannels channels;
    channels.height = int(image.shape(0));
    channels.width = int(image.shape(1));
    for (int c = 0; c < kChannels; ++c) {
      std::vector<float>& plane = channels.planes[kChannelNames[c]];
      plane.reserve(size_t(channels.width) * channels.height);
      for (py::ssize_t y = 0; y < view.shape(0); ++y)
        for (py::ssize_t x = 0; x < view.shape(1); ++x) plane.push_back(view(y, x, c));
    }
    labels.push_back(label);
    images.push_back(std::move(channels));
  }
  return {std::move(labels), std::move(images)};
}

bool isFileName(const py::handle& item) {
  return py::isinstance<py::str>(item) ||
         py::isinstance(item, py::module_::import("os").attr("PathLike"));
}

// One side's file names when every item of `side` is a str or an os.PathLike; nothing when
// none is (arrays, or no sequence: renders() says what is wrong). A side mixing both is refused.
std::optional<std::vector<std::filesystem::path>> fileNames(const py::object& side,
                                                            const std::string& name) {
  if (isFileName(side))
    throw py::type_error(fmt::format(
        "verity.compare: {} is one file name, {}; give the side's renders as a sequence of them",
        name, py::repr(side).cast<std::string>()));
  if (py::isinstance<py::array>(side) || !py::isinstance<py::sequence>(side)) return {};
  const py::sequence items = py::reinterpret_borrow<py::sequence>(side);
  std::vector<std::filesystem::path> files;
  std::optional<size_t> array, named;  // the first item that is not a file name, that is one
  for (size_t r = 0; r < py::len(items); ++r) {
    if (!isFileName(items[r])) {
      if (!array) array = r;
      continue;
    }
    if (!named) named = r;
    const py::object text = py::module_::import("os").attr("fspath")(items[r]);
    files.emplace_back(py::isinstance<py::bytes>(text) ? std::string(py::bytes(text))
                                                       : text.cast<std::string>());
  }
  if (files.empty()) return {};
  if (array)
    throw py::type_error(fmt::format(
        "verity.compare: {0} mixes file names and arrays ({0}[{1}] is a file name, {0}[{2}] "
        "of type {3}); give a side as renders' file names or as arrays, not both",
        name, *named, *array,
        py::str(py::type::of(items[*array]).attr("__name__")).cast<std::string>()));
  return files;
}

CompareDecision compare(const py::object& a, const py::object& b, int tile, double alpha,
                        const py::object& margin, double power) {
  validation::ComparisonOptions options;
  options.tileSize = tile;
  options.alpha = alpha;
  options.power = power;
  const double m = margin.is_none() ? 0 : margin.cast<double>();
  if (!margin.is_none() && !(m > 0))
    throw py::value_error(
        fmt::format("verity.compare: margin must be above 0 (or None), not {}", m));
  py::array firstA, firstB;
  std::vector<std::string> labelsA, labelsB;
  std::vector<ImageChannels> imagesA, imagesB;
  const auto filesA = fileNames(a, "a");
  if (!filesA) std::tie(labelsA, imagesA) = renders(a, "a", nullptr, &firstA);
  const auto filesB = fileNames(b, "b");
  if (!filesB) std::tie(labelsB, imagesB) = renders(b, "b", filesA ? nullptr : &firstA, &firstB);
  // The library's errors (VerityError: options, files that cannot be read, renders with the
  // same pixels) are the caller's.
  try {
    validation::checkCompareOptions(options, m);
    py::gil_scoped_release release;
    // Files are read as `verity compare -a ... -b ...` reads them: all distinct, then each
    // side (one file with variance channels, or a set of renders). Arrays make a set whose
    // sides keep only R, G and B and mark non-finite pixels, left out of both sides, as the
    // command does with EXR files.
    std::vector<std::filesystem::path> all = filesA.value_or(std::vector<std::filesystem::path>{});
    if (filesB) all.insert(all.end(), filesB->begin(), filesB->end());
    validation::requireDistinctFiles(all);
    const auto side = [](const auto& files, std::vector<std::string>& labels,
                         const std::vector<ImageChannels>& images,
                         const std::string& name) -> std::unique_ptr<validation::ComparisonSide> {
      if (files) return validation::loadSide(*files, name, "");
      return std::make_unique<validation::RenderSetSide>(std::move(labels), images, "");
    };
    const auto sideA = side(filesA, labelsA, imagesA, "A");
    const auto sideB = side(filesB, labelsB, imagesB, "B");
    return validation::decideComparison(*sideA, *sideB, options, m);
  } catch (const std::runtime_error& e) {
    throw py::value_error(std::string("verity.compare: ") + e.what());
  }
}

py::object toPython(const nlohmann::json& json) {
  return py::module_::import("json").attr("loads")(json.dump());
}

}  // namespace

void bindCompare(py::module_& m) {
  py::class_<TileTest>(m, "TileTest", "One tile and channel's Welch t-test.")
      .def_readonly("tile_x", &TileTest::tileX)
      .def_readonly("tile_y", &TileTest::tileY)
      .def_property_readonly(
          "channel", [](const TileTest& t) { return std::string(kChannelNames[t.channel]); })
      .def_property_readonly("pixels", [](const TileTest& t) { return t.pooled.pixels; })
      .def_property_readonly("mean_a", [](const TileTest& t) { return t.pooled.a.mean; })
      .def_property_readonly("mean_b", [](const TileTest& t) { return t.pooled.b.mean; })
      .def_readonly("relative_difference", &TileTest::relativeDifference)
      .def_property_readonly("t", [](const TileTest& t) { return t.welch.t; })
      .def_property_readonly("df", [](const TileTest& t) { return t.welch.df; })
      .def_property_readonly("p", [](const TileTest& t) { return t.welch.p; })
      .def_readonly("z", &TileTest::z)
      .def_readonly("adjusted_p", &TileTest::adjustedP, "Holm-adjusted p")
      .def_readonly("rejected", &TileTest::rejected)
      .def_readonly("detectable_bias", &TileTest::detectableBias,
                    "the smallest relative bias of this tile found with the given power")
      .def("__repr__", [](const TileTest& t) {
        return fmt::format("<TileTest tile ({}, {}) {}: p {:.3g}, Holm p {:.3g}{}>", t.tileX,
                           t.tileY, kChannelNames[t.channel], t.welch.p, t.adjustedP,
                           t.rejected ? ", rejected" : "");
      });
  py::class_<CompareDecision>(m, "Comparison",
                              "What verity.compare decided; str() is `verity compare`'s summary.")
      .def_property_readonly("verdict", &CompareDecision::verdict,
                             "'DIFFER', 'AGREE' or, with a margin, 'EQUIVALENT' or "
                             "'EQUIVALENCE NOT SHOWN'")
      .def_property_readonly("differ", [](const CompareDecision& d) { return d.comparison.differ; })
      .def_property_readonly(
          "tests", [](const CompareDecision& d) { return d.comparison.tests; },
          "every tile and channel's test, tile-major")
      .def_property_readonly("rejected",
                             [](const CompareDecision& d) {
                               std::vector<TileTest> out;
                               for (const TileTest& t : d.comparison.tests)
                                 if (t.rejected) out.push_back(t);
                               return out;
                             })
      .def_property_readonly("power",
                             [](const CompareDecision& d) { return d.comparison.options.power; })
      .def_property_readonly(
          "detectable_bias", [](const CompareDecision& d) { return d.comparison.detectableBias; },
          "the smallest uniform relative bias of B found with probability `power` (inf: none)")
      .def_property_readonly(
          "equivalence",
          [](const CompareDecision& d) {
            return d.equivalence ? toPython(d.json["equivalence"]) : py::object(py::none());
          },
          "with a margin: margin, level, verdict, claimable_margin and each test's one-sided "
          "p-values (as in the JSON); None without")
      .def_property_readonly(
          "claimable_margin",
          [](const CompareDecision& d) -> py::object {
            if (!d.equivalence) return py::none();
            return py::float_(validation::claimableImageMargin(d.comparison, *d.equivalence));
          })
      .def(
          "to_json", [](const CompareDecision& d) { return d.json.dump(2); },
          "`verity compare -o`'s JSON, as text")
      .def("to_dict", [](const CompareDecision& d) { return toPython(d.json); })
      .def("__str__", [](const CompareDecision& d) { return d.summary; })
      .def("__repr__",
           [](const CompareDecision& d) { return fmt::format("<Comparison {}>", d.verdict()); });
  m.def("compare", &compare, py::arg("a"), py::arg("b"), py::arg("tile") = 16,
        py::arg("alpha") = 0.01, py::arg("margin") = py::none(), py::arg("power") = 0.9,
        R"(Do two sets of renders estimate the same image? `verity compare -a ... -b ...` on
arrays or files: each of a and b is a sequence of (H, W, 3) float arrays (or an (N, H, W, 3)
array), each an independent render (its own seed), at least 2 per side; or a sequence of EXR
file names (str or os.PathLike), read as the command reads -a and -b (R, G and B found as it
finds them; one file must have variance channels, as from `verity render --variance`). A side
is arrays or names, not both; a file that cannot be read raises ValueError naming it. Per-tile
Welch t-tests (tile x tile pixels, per channel) decided by Holm's procedure at family-wise
level alpha; with margin, also equivalence within that relative margin of a (two one-sided
tests per tile at alpha). Pixels with a non-finite value in any render are left out of both
sides. Returns a Comparison.)");
}

}  // namespace verity::python
