// gdel._core: the nanobind layer over the public C++ API (include/gdel/*.hpp) and
// nothing else. Arrays come in as host ndarrays (numpy or any DLPack producer),
// are read in place when they already are contiguous float64 / int32 and converted
// once otherwise; results leave as numpy arrays owning the API's vectors. The GIL
// is released while reading inputs and computing. CUDA arrays go to
// gdel::delaunay_device (delaunay_device below): read in place on their GPU, results
// returned as torch/cupy arrays owning gdel's device memory.
#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>

#include <optional>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "gdel/delaunay.hpp"
#include "gdel/device_memory.hpp"
#include "gdel/errors.hpp"
#include "gdel/options.hpp"
#include "gdel/regular.hpp"
#include "gdel/verify.hpp"
#include "gdel/version.hpp"

namespace nb = nanobind;
using namespace nb::literals;
using gdel_py::AnyArray;

namespace {

// Python exception types (module attributes, created once at import and kept for the
// life of the process).
PyObject* g_gdel_error = nullptr;         // gdel.GdelError(RuntimeError)
PyObject* g_degenerate_error = nullptr;   // gdel.DegenerateInputError(ValueError)
PyObject* g_backend_error = nullptr;      // gdel.BackendUnavailableError(GdelError)

void translate(const std::exception_ptr& p, void*) {
  try {
    std::rethrow_exception(p);
  } catch (const gdel::InvalidInput& e) {
    PyErr_SetString(PyExc_ValueError, e.what());
  } catch (const gdel::DegenerateInput& e) {
    PyErr_SetString(g_degenerate_error, e.what());
  } catch (const gdel::OutOfDeviceMemory& e) {
    // MemoryError carrying the byte counts as attributes as well as in the text.
    std::string msg = std::string(e.what()) + " [needed " + std::to_string(e.needed) + " bytes, " +
                      (e.available ? std::to_string(e.available) + " bytes free" : std::string("free unknown")) +
                      "]";
    nb::object exc = nb::steal(PyObject_CallFunction(PyExc_MemoryError, "s", msg.c_str()));
    if (!exc.is_valid()) return;  // the call set its own error
    nb::setattr(exc, "needed", nb::int_(e.needed));
    nb::setattr(exc, "available", nb::int_(e.available));
    PyErr_SetObject(PyExc_MemoryError, exc.ptr());
  } catch (const gdel::BackendUnavailable& e) {
    PyErr_SetString(g_backend_error, e.what());
  } catch (const gdel::Error& e) {  // CudaError and any later gdel error
    PyErr_SetString(g_gdel_error, e.what());
  }
}

// Named after the module as imported ("gdel._core"; "_core" when stubgen imports the
// built file alone, so that the stub declares the classes); gdel/__init__.py shows
// them as gdel.<Name>.
PyObject* new_exception(nb::module_& m, const char* name, PyObject* base, const char* doc) {
  const std::string qualified = nb::cast<std::string>(m.attr("__name__")) + "." + name;
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, base, nullptr);
  if (!type) throw nb::python_error();
  m.attr(name) = nb::borrow(type);  // the module holds a reference; ours stays for the process
  return type;
}

// The names accepted for algorithm= and device= are the C++ to_string() of each
// enumerator ("auto", "gflip3d", "gdel3d", ... and "auto", "cpu", "cuda"), so an
// enumerator added to the C++ API appears here without a change: enumerators are
// contiguous from 0 and to_string() answers "?" past the last one.
template <class E>
std::vector<E> enumerators() {
  std::vector<E> v;
  for (int i = 0; i < 64 && std::string(gdel::to_string(static_cast<E>(i))) != "?"; ++i) v.push_back(static_cast<E>(i));
  return v;
}

template <class E>
E parse_name(const std::string& s, const char* what) {
  std::string choices;
  for (E v : enumerators<E>()) {
    if (s == gdel::to_string(v)) return v;
    choices += std::string(choices.empty() ? "" : ", ") + "'" + gdel::to_string(v) + "'";
  }
  throw nb::value_error((std::string("unknown ") + what + " '" + s + "'; choose one of " + choices).c_str());
}

template <class E>
nb::tuple names() {
  nb::list l;
  for (E v : enumerators<E>()) l.append(nb::str(gdel::to_string(v)));
  return nb::tuple(l);
}

void require_host(const AnyArray& a, const char* what) {
  if (!gdel_py::host_accessible(a.device_type()))
    throw nb::type_error((std::string(what) + ": gdel._core reads host memory only; this array is on DLPack device type " +
                          std::to_string(a.device_type()) + " (gdel.Delaunay moves CUDA arrays through the host)")
                             .c_str());
}

void require_points_shape(const AnyArray& a, const char* what) {
  if (a.ndim() != 2 || a.shape(1) != 3)
    throw nb::value_error((std::string(what) + ": expected an array of shape (n, 3), got shape " +
                           gdel_py::shape_string(a))
                              .c_str());
}

nb::dict stats_dict(const gdel::Stats& s) {
  nb::dict d;
  d["algorithm"] = s.algorithm;
  d["backend"] = s.backend;
  d["seconds"] = s.seconds;
  nb::dict stages;
  for (const auto& [name, t] : s.stages) stages[nb::str(name.c_str())] = t;
  d["stages"] = stages;
  d["points"] = s.points;
  d["distinct_points"] = s.distinct_points;
  d["rounds"] = s.rounds;
  d["flip_iterations"] = s.flip_iterations;
  d["sos_order_round"] = s.sos_order_round;
  d["kernel_point_centroid"] = s.kernel_point_centroid;
  d["flips23"] = s.flips23;
  d["flips32"] = s.flips32;
  d["exact_evaluations"] = s.exact_evaluations;
  d["failed_vertices"] = s.failed_vertices;
  d["repair_failed_vertices"] = s.repair_failed_vertices;
  d["stars_built"] = s.stars_built;
  d["stars_flipflop"] = s.stars_flipflop;
  d["stars_rebuilt"] = s.stars_rebuilt;
  d["stars_built_on_host"] = s.stars_built_on_host;
  d["host_star_insertions"] = s.host_star_insertions;
  d["points_deferred"] = s.points_deferred;
  d["stars_pulled"] = s.stars_pulled;
  d["splay_rounds"] = s.splay_rounds;
  d["splay_insertions"] = s.splay_insertions;
  d["flat_tets_removed"] = s.flat_tets_removed;
  d["grid"] = s.grid;
  d["working_set_pairs"] = s.working_set_pairs;
  d["certificate_fallbacks"] = s.certificate_fallbacks;
  d["dead_stars"] = s.dead_stars;
  d["redundant_points"] = s.redundant_points;
  d["peak_bytes"] = s.peak_bytes;
  d["verify_summary"] = s.verify_summary;
  d["summary"] = s.to_string();
  return d;
}

nb::dict report_dict(const gdel::VerifyReport& r) {
  nb::dict d;
  d["points"] = r.points;
  d["distinct_points"] = r.distinct_points;
  d["tets"] = r.tets;
  d["vertices_used"] = r.vertices_used;
  d["edges"] = r.edges;
  d["facets"] = r.facets;
  d["hull_facets"] = r.hull_facets;
  d["euler"] = r.euler;
  d["bad_index"] = r.bad_index;
  d["degenerate_tets"] = r.degenerate_tets;
  d["inverted_tets"] = r.inverted_tets;
  d["overshared_facets"] = r.overshared_facets;
  d["same_side_facets"] = r.same_side_facets;
  d["hull_open_edges"] = r.hull_open_edges;
  d["hull_reflex_edges"] = r.hull_reflex_edges;
  d["unused_points"] = r.unused_points;
  d["duplicate_vertices"] = r.duplicate_vertices;
  d["locate_failures"] = r.locate_failures;
  d["euler_ok"] = r.euler_ok;
  d["non_delaunay_facets"] = r.non_delaunay_facets;
  d["cospherical_facets"] = r.cospherical_facets;
  d["redundant_points"] = r.redundant_points;
  d["exact_evaluations"] = r.exact_evaluations;
  d["seconds"] = r.seconds;
  d["valid"] = r.valid();
  d["delaunay"] = r.delaunay();
  d["summary"] = r.summary();
  return d;
}

nb::dict py_delaunay(const AnyArray& points, const std::string& algorithm, const std::string& backend, int ordinal) {
  require_host(points, "points");
  require_points_shape(points, "points");
  gdel::Options opt;
  opt.algorithm = parse_name<gdel::Algorithm>(algorithm, "algorithm");
  opt.backend = parse_name<gdel::Backend>(backend, "device");
  opt.device = ordinal;
  gdel_py::Contiguous<double> pts;
  gdel::Triangulation t;
  {
    nb::gil_scoped_release unlocked;
    pts = gdel_py::as_doubles(points, "points");
    t = gdel::delaunay(pts.view, opt);
  }
  const std::size_t n = points.shape(0);
  const std::size_t m = static_cast<std::size_t>(t.num_tets());
  const std::size_t nf = t.failed_vertices.size();
  nb::dict d;
  d["simplices"] = gdel_py::to_numpy(std::move(t.tets), {m, 4});
  d["neighbors"] = gdel_py::to_numpy(std::move(t.neighbors), {m, 4});
  d["failed_vertices"] = gdel_py::to_numpy(std::move(t.failed_vertices), {nf});
  d["representative"] = gdel_py::to_numpy(std::move(t.representative), {n});
  d["stats"] = stats_dict(t.stats);
  // The float64 copy the library triangulated, when the input was not already one
  // (the Python layer keeps it as Delaunay.points instead of converting again).
  d["points"] = pts.converted ? gdel_py::to_numpy(std::move(pts.owned), {n, 3}) : nb::none();
  return d;
}

// gdel::regular on host arrays: points (n, 3) and weights (n,).
nb::dict py_regular(const AnyArray& points, const AnyArray& weights, const std::string& algorithm,
                    const std::string& backend, int ordinal, bool certificates) {
  require_host(points, "points");
  require_points_shape(points, "points");
  require_host(weights, "weights");
  if (weights.ndim() != 1 || weights.shape(0) != points.shape(0))
    throw nb::value_error(("weights: expected an array of shape (" + std::to_string(points.shape(0)) +
                           ",) (one per point), got shape " + gdel_py::shape_string(weights))
                              .c_str());
  gdel::Options opt;
  opt.algorithm = parse_name<gdel::Algorithm>(algorithm, "algorithm");
  opt.backend = parse_name<gdel::Backend>(backend, "device");
  opt.device = ordinal;
  opt.certificates = certificates;
  gdel_py::Contiguous<double> pts, w;
  gdel::RegularTriangulation t;
  {
    nb::gil_scoped_release unlocked;
    pts = gdel_py::as_doubles(points, "points");
    w = gdel_py::as_doubles(weights, "weights");
    t = gdel::regular(pts.view, w.view, opt);
  }
  const std::size_t n = points.shape(0);
  const std::size_t m = static_cast<std::size_t>(t.num_tets());
  const std::size_t k = t.redundant.size();
  nb::dict d;
  d["simplices"] = gdel_py::to_numpy(std::move(t.tets), {m, 4});
  d["neighbors"] = gdel_py::to_numpy(std::move(t.neighbors), {m, 4});
  d["redundant"] = gdel_py::to_numpy(std::move(t.redundant), {k});
  d["representative"] = gdel_py::to_numpy(std::move(t.representative), {n});
  d["certificates"] = certificates ? gdel_py::to_numpy(std::move(t.certificates), {k, 5}) : nb::none();
  d["stats"] = stats_dict(t.stats);
  d["points"] = pts.converted ? gdel_py::to_numpy(std::move(pts.owned), {n, 3}) : nb::none();
  d["weights"] = w.converted ? gdel_py::to_numpy(std::move(w.owned), {n}) : nb::none();
  return d;
}

// CUDA (or managed) arrays, read where they are by gdel::delaunay_device; results are
// `framework` arrays on the same device that own gdel's device memory. The Python layer
// (gdel/_arrays.py) makes the input C-contiguous float32/float64 with the framework's own
// device operations and passes the framework's current stream.
nb::dict py_delaunay_device(const AnyArray& points, const std::string& framework, const std::string& algorithm,
                            std::uintptr_t stream) {
  const int dt = points.device_type();
  if (dt != nb::device::cuda::value && dt != nb::device::cuda_managed::value)
    throw nb::type_error(("points: delaunay_device takes CUDA arrays; this one is on DLPack device type " +
                          std::to_string(dt))
                             .c_str());
  require_points_shape(points, "points");
  const bool f64 = points.dtype() == nb::dtype<double>();
  if (!f64 && points.dtype() != nb::dtype<float>())
    throw nb::value_error(("points: delaunay_device takes float32 or float64, got dtype " +
                           gdel_py::dtype_name(points.dtype()))
                              .c_str());
  if (!gdel_py::c_contiguous(points))
    throw nb::value_error("points: delaunay_device takes C-contiguous arrays (make it contiguous on the device first)");
  if (framework != "torch" && framework != "cupy")
    throw nb::value_error(("delaunay_device: framework '" + framework + "' (torch or cupy)").c_str());
  gdel::Options opt;
  opt.algorithm = parse_name<gdel::Algorithm>(algorithm, "algorithm");
  opt.backend = gdel::Backend::Cuda;
  gdel::DevicePoints dp;
  dp.data = static_cast<const std::uint8_t*>(points.data_handle()) + points.byte_offset();
  dp.n = static_cast<std::int64_t>(points.shape(0));
  dp.float32 = !f64;
  dp.device = points.device_id();
  dp.stream = reinterpret_cast<void*>(stream);
  opt.device = dp.device;
  gdel::DeviceTriangulation t;
  {
    nb::gil_scoped_release unlocked;
    t = gdel::delaunay_device(dp, opt);
  }
  const std::size_t n = points.shape(0);
  const std::size_t m = static_cast<std::size_t>(t.num_tets());
  const std::size_t nf = static_cast<std::size_t>(t.failed_vertices.size());
  nb::dict d;
  d["simplices"] = gdel_py::to_device_framework(std::move(t.tets), m, 4, framework);
  d["neighbors"] = gdel_py::to_device_framework(std::move(t.neighbors), m, 4, framework);
  d["failed_vertices"] = gdel_py::to_device_framework(std::move(t.failed_vertices), nf, 0, framework);
  d["representative"] = gdel_py::to_device_framework(std::move(t.representative), n, 0, framework);
  d["nsimplex"] = m;
  nb::dict st = stats_dict(t.stats);
  // What the C++ side received and read: the proof that the points were not copied
  // (points_read == the input's data pointer unless converted says otherwise).
  nb::dict din;
  din["device"] = dp.device;
  din["received"] = reinterpret_cast<std::uintptr_t>(dp.data);
  din["points_read"] = reinterpret_cast<std::uintptr_t>(t.points_read);
  din["converted"] = t.converted_input;
  din["stream"] = stream;
  st["device_input"] = din;
  d["stats"] = st;
  return d;
}

nb::dict py_verify(const AnyArray& points, const AnyArray& tets, std::optional<AnyArray> weights,
                   const std::string& backend) {
  require_host(points, "points");
  require_points_shape(points, "points");
  require_host(tets, "simplices");
  if (tets.ndim() != 2 || tets.shape(1) != 4)
    throw nb::value_error(
        ("simplices: expected an array of shape (m, 4), got shape " + gdel_py::shape_string(tets)).c_str());
  if (weights) {
    require_host(*weights, "weights");
    if (weights->ndim() != 1 || weights->shape(0) != points.shape(0))
      throw nb::value_error(("weights: expected an array of shape (" + std::to_string(points.shape(0)) +
                             ",) (one per point), got shape " + gdel_py::shape_string(*weights))
                                .c_str());
  }
  const gdel::Backend b = parse_name<gdel::Backend>(backend, "device");
  gdel::VerifyReport r;
  {
    nb::gil_scoped_release unlocked;
    auto p = gdel_py::as_doubles(points, "points");
    auto t = gdel_py::as_int32(tets, "simplices");
    gdel_py::Contiguous<double> w;
    if (weights) w = gdel_py::as_doubles(*weights, "weights");
    r = gdel::verify(p.view, t.view, w.view, b);
  }
  return report_dict(r);
}

// Test seam: throws the named gdel exception so that the translation table above can
// be checked without provoking each condition for real (device OOM needs a GPU).
void py_raise(const std::string& kind, const std::string& message) {
  if (kind == "InvalidInput") throw gdel::InvalidInput(message);
  if (kind == "DegenerateInput") throw gdel::DegenerateInput(message);
  if (kind == "OutOfDeviceMemory") throw gdel::OutOfDeviceMemory(message, 1234, 56);
  if (kind == "CudaError") throw gdel::CudaError(message);
  if (kind == "BackendUnavailable") throw gdel::BackendUnavailable(message);
  if (kind == "Error") throw gdel::Error(message);
  throw nb::value_error(("_raise: unknown kind " + kind).c_str());
}

}  // namespace

NB_MODULE(_core, m) {
  m.doc() = "gdel's compiled layer over the C++ API. Use the `gdel` package, not this module.";

  g_gdel_error = new_exception(m, "GdelError", PyExc_RuntimeError,
                               "A gdel failure that is not about the input (for example a CUDA error).");
  g_degenerate_error = new_exception(
      m, "DegenerateInputError", PyExc_ValueError,
      "The input has no 3-D triangulation: fewer than 4 distinct points, or all points coplanar or collinear.");
  g_backend_error = new_exception(m, "BackendUnavailableError", g_gdel_error,
                                  "The requested backend is not in this build or no device is visible.");
  nb::register_exception_translator(translate);

  m.attr("ALGORITHMS") = names<gdel::Algorithm>();
  m.attr("DEVICES") = names<gdel::Backend>();

  m.def("delaunay", &py_delaunay, "points"_a, "algorithm"_a = "auto", "backend"_a = "auto", "ordinal"_a = 0,
        nb::sig("def delaunay(points: typing.Any, algorithm: str = 'auto', backend: str = 'auto', ordinal: int = 0) "
                "-> dict[str, typing.Any]"),
        "Triangulates host points of shape (n, 3) (float32/float64/integer, any strides) with\n"
        "algorithm and backend given by name, on CUDA device `ordinal` when the backend is CUDA.\n\n"
        "Returns a dict: simplices (m, 4) int32, neighbors (m, 4) int32, failed_vertices (k,) int32,\n"
        "representative (n,) int32, stats (dict), points (the float64 copy when the input was converted,\n"
        "else None). The GIL is released while computing.");
  m.def("delaunay_device", &py_delaunay_device, "points"_a, "framework"_a, "algorithm"_a = "auto", "stream"_a = 0,
        nb::sig("def delaunay_device(points: typing.Any, framework: str, algorithm: str = 'auto', stream: int = 0) "
                "-> dict[str, typing.Any]"),
        "Triangulates C-contiguous float32/float64 points of shape (n, 3) in CUDA memory on their own\n"
        "device (gdel::delaunay_device: no host copy of the points or the results). `framework`\n"
        "('torch' or 'cupy') is the kind of the result arrays; `stream` the cudaStream_t the points\n"
        "were written on (0: the legacy default stream), which gdel waits for.\n\n"
        "Returns a dict: simplices, neighbors (m, 4), failed_vertices (k,), representative (n,) as int32\n"
        "device arrays owning gdel's memory (None where empty), nsimplex, stats (with\n"
        "stats['device_input']: received / points_read pointers, converted). The GIL is released.");
  m.def("regular", &py_regular, "points"_a, "weights"_a, "algorithm"_a = "auto", "backend"_a = "auto",
        "ordinal"_a = 0, "certificates"_a = false,
        nb::sig("def regular(points: typing.Any, weights: typing.Any, algorithm: str = 'auto', backend: str = 'auto', "
                "ordinal: int = 0, certificates: bool = False) -> dict[str, typing.Any]"),
        "Regular (weighted Delaunay) triangulation of host points (n, 3) with weights (n,) (gdel::regular).\n\n"
        "Returns a dict: simplices (m, 4) int32, neighbors (m, 4) int32, redundant (k,) int32,\n"
        "representative (n,) int32, certificates (k, 5) int32 or None, stats (dict), points and weights\n"
        "(the float64 copies when the inputs were converted, else None). The GIL is released while computing.");
  m.def("verify", &py_verify, "points"_a, "simplices"_a, "weights"_a = nb::none(), "backend"_a = "auto",
        nb::sig("def verify(points: typing.Any, simplices: typing.Any, weights: typing.Any | None = None, "
                "backend: str = 'auto') -> dict[str, typing.Any]"),
        "Exact verification (gdel::verify) of simplices (m, 4) over points (n, 3); returns the report as a dict.");
  m.def("version", [] { return std::string(gdel::version()); }, "The library version.");
  m.def("built_with_cuda", &gdel::built_with_cuda, "True when this build contains the CUDA backend.");
  m.def("cuda_device_available", &gdel::cuda_device_available,
        "True when this build has the CUDA backend and a CUDA device is visible.");
  m.def("keep_device_memory", &gdel::keep_device_memory, "nbytes"_a,
        "Keep up to nbytes of freed device memory between calls (gdel/device_memory.hpp); 0: none.");
  m.def("release_device_memory", &gdel::release_device_memory, "Give the device memory kept between calls back now.");
  m.def("kept_device_memory_bound", &gdel::kept_device_memory_bound, "The bytes kept between calls at most (0: none).");
  m.def("_raise", &py_raise, "kind"_a, "message"_a, "Test seam: throws the named gdel C++ exception.");
}
