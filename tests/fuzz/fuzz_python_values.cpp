// The libFuzzer target of the Python module's value conversion: the input is a small program that
// builds Python values (numbers of any size, text, None, lists, tuples, dicts, numpy arrays,
// values nested deep or holding themselves), handed to sansui.Recipe() as a recipe and to
// sansui.midpoint() and sansui.erode() as keyword arguments. Every call must return or raise
// TypeError or ValueError with a whole one-line message; anything else (another exception, a
// message cut short, a crash of the interpreter) is a finding. The interpreter is embedded, and
// the sanitizer build's own extension module is imported: build-sanitize/python, beside this
// program (found at run time: a macro with the build's path would make ccache miss this file in
// every fresh clone).
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <pybind11/embed.h>
#include <pybind11/stl.h>

namespace py = pybind11;

namespace {

/// Reads the input a byte at a time (zeros past its end).
struct Bytes {
  const std::uint8_t* data;
  std::size_t size, at = 0;
  bool done() const { return at >= size; }
  std::uint8_t next() { return at < size ? data[at++] : 0; }
  template <class T>
  T value() {
    T v{};
    unsigned char raw[sizeof(T)] = {};
    for (auto& byte : raw) byte = next();
    std::memcpy(&v, raw, sizeof v);
    return v;
  }
};

/// Keys the values are given under: real parameters of the functions, and a few that are not.
const std::vector<std::string> keys = {"seed",     "hurst",  "sigma", "land_fraction", "stage",    "erosion_steps", "size",   "cell",
                                       "progress", "points", "hurts", "world",         "midpoint", "shape",         "output", "node"};

py::object build(Bytes& in) {
  std::vector<py::object> stack;
  const auto pop = [&] {
    py::object top = std::move(stack.back());
    stack.pop_back();
    return top;
  };
  for (int steps = 0; !in.done() && steps < 256; ++steps) {
    switch (in.next() % 12) {
      case 0:
        stack.push_back(py::int_(in.value<std::int64_t>()));
        break;
      case 1:
        stack.push_back(py::float_(in.value<double>()));
        break;
      case 2: {
        std::string text;
        for (int n = in.next() % 24; n > 0; --n) text += static_cast<char>(in.next());
        stack.push_back(
            py::reinterpret_steal<py::object>(PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()), "replace")));
        break;
      }
      case 3:
        stack.push_back(py::bool_(in.next() % 2 == 0));
        break;
      case 4:
        stack.push_back(py::none());
        break;
      case 5:
      case 7: {
        py::list list;
        for (int n = in.next() % 6; n > 0 && !stack.empty(); --n) list.append(pop());
        stack.push_back(in.at % 2 == 0 ? py::object(list) : py::object(py::tuple(list)));
        break;
      }
      case 6: {
        py::dict dict;
        for (int n = in.next() % 4; n > 0 && !stack.empty(); --n) dict[py::str(keys[in.next() % keys.size()])] = pop();
        stack.push_back(dict);
        break;
      }
      case 8:
        if (!stack.empty()) stack.push_back(stack.back());
        break;
      case 9:  // a container that holds itself
        if (!stack.empty() && py::isinstance<py::list>(stack.back())) stack.back().cast<py::list>().append(stack.back());
        if (!stack.empty() && py::isinstance<py::dict>(stack.back())) stack.back()[py::str(keys[in.next() % keys.size()])] = stack.back();
        break;
      case 10: {  // nested deep: {"world": {"world": ...}} or [[...]]
        if (stack.empty()) break;
        py::object inner = pop();
        const int depth = in.value<std::uint16_t>() % 5000;
        const bool lists = in.next() % 2 == 0;
        for (int d = 0; d < depth; ++d) {
          if (lists) {
            py::list l;
            l.append(inner);
            inner = l;
          } else {
            py::dict n;
            n["world"] = inner;
            inner = n;
          }
        }
        stack.push_back(inner);
        break;
      }
      default: {
        const int rows = 1 + in.next() % 40, columns = 1 + in.next() % 40;
        py::module_ numpy = py::module_::import("numpy");
        stack.push_back(
            numpy.attr("full")(py::make_tuple(rows, columns), py::float_(in.value<float>()), in.next() % 2 == 0 ? "float32" : "float64"));
      }
    }
  }
  return stack.empty() ? py::object(py::dict()) : stack.back();
}

/// Calls `call`; a TypeError or ValueError with a whole message is an answer; anything else aborts.
/// A message that quotes the input may hold any text, "internal error" too (a finding of a CI
/// run): only one that starts so is one.
template <class Call>
void expect_answer(Call&& call) {
  try {
    call();
  } catch (py::error_already_set& error) {
    const bool allowed = error.matches(PyExc_TypeError) || error.matches(PyExc_ValueError);
    const std::string message = py::str(error.value());
    const bool whole = !message.empty() && message.find('\n') == std::string::npos && !message.ends_with("must be ") &&
                       !message.starts_with("internal error");
    if (!allowed || !whole) {
      std::fprintf(stderr, "python_values: %s: %s\n", py::str(error.type().attr("__name__")).cast<std::string>().c_str(), message.c_str());
      std::abort();
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  static py::scoped_interpreter interpreter;
  const std::filesystem::path python = std::filesystem::read_symlink("/proc/self/exe").parent_path() / "python";
  py::module_::import("sys").attr("path").attr("insert")(0, python.string());
  py::module_::import("sansui");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes in{data, size};
  const int call = in.next() % 3;
  const std::string key = keys[in.next() % keys.size()];
  py::object value = build(in);
  py::module_ sansui = py::module_::import("sansui");
  if (call == 0) {
    expect_answer([&] { sansui.attr("Recipe")(value); });
  } else if (call == 1) {
    py::dict arguments;
    arguments["size"] = 33;
    arguments[py::str(key)] = value;
    expect_answer([&] { sansui.attr("midpoint")(**arguments); });
  } else {
    // Many erosion steps are real work, not a hang (about 1 ms a step under ASan on any grid,
    // 100000 allowed): past 1000 the input says nothing new about the conversion.
    if (key == "erosion_steps" && py::isinstance<py::int_>(value) && py::int_(1000) < value) return 0;
    py::dict arguments;
    arguments[py::str(key)] = value;
    py::object heights = py::module_::import("numpy").attr("zeros")(py::make_tuple(17, 17), "float32");
    expect_answer([&] { sansui.attr("erode")(heights, **arguments); });
  }
  return 0;
}
