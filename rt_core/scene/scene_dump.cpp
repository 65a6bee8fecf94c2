#include "rt_core/scene/scene_dump.hpp"

#include <cstdio>
#include <cstring>
#include <memory>
#include <type_traits>

namespace glpt::rt {
namespace {

constexpr char kMagic[8] = {'G', 'L', 'P', 'T', 'S', 'C', 'N', '1'};
// A bound on counts read from a file, so a corrupt header cannot ask for absurd allocations.
constexpr uint64_t kMaxCount = uint64_t{1} << 32;

struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

class Writer {
 public:
  explicit Writer(std::FILE* file) : file_(file) {}
  template <typename T>
  void value(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes(&v, sizeof v);
  }
  void bytes(const void* data, size_t size) {
    if (ok_ && size != 0) ok_ = std::fwrite(data, 1, size, file_) == size;
  }
  bool ok() const { return ok_; }

 private:
  std::FILE* file_;
  bool ok_ = true;
};

class Reader {
 public:
  explicit Reader(std::FILE* file) : file_(file) {}
  template <typename T>
  T value() {
    static_assert(std::is_trivially_copyable_v<T>);
    T v{};
    bytes(&v, sizeof v);
    return v;
  }
  void bytes(void* data, size_t size) {
    if (ok_ && size != 0) ok_ = std::fread(data, 1, size, file_) == size;
  }
  // A count, then that many floats times `per_item`.
  bool floats(std::vector<float>& out, uint64_t count, uint64_t per_item) {
    if (!ok_ || count > kMaxCount) return ok_ = false;
    out.resize(count * per_item);
    bytes(out.data(), out.size() * sizeof(float));
    return ok_;
  }
  bool ok() const { return ok_; }
  bool fail() { return ok_ = false; }

 private:
  std::FILE* file_;
  bool ok_ = true;
};

}  // namespace

void place_instances(SceneDump& dump) {
  dump.eye_triangles.clear();
  for (SceneDumpInstance& instance : dump.instances) {
    instance.first_triangle = dump.eye_triangles.size() / 9;
    instance.triangle_count = 0;
    if (instance.shape >= dump.shapes.size()) continue;
    const std::vector<float>& p = dump.shapes[instance.shape].positions;
    const std::array<float, 12>& m = instance.transform;
    for (size_t v = 0; v + 2 < p.size(); v += 3)
      for (int row = 0; row < 3; ++row)
        dump.eye_triangles.push_back(m[4 * row] * p[v] + m[4 * row + 1] * p[v + 1] +
                                     m[4 * row + 2] * p[v + 2] + m[4 * row + 3]);
    instance.triangle_count = static_cast<uint32_t>(p.size() / 9);
  }
}

bool write_scene_dump(const std::string& path, const SceneDump& dump, std::string* error) {
  File file(std::fopen(path.c_str(), "wb"));
  if (!file) {
    if (error != nullptr) *error = "cannot open " + path + " for writing";
    return false;
  }
  Writer w(file.get());
  w.bytes(kMagic, sizeof kMagic);
  w.value(SceneDump::kVersion);
  w.value(dump.frame);
  w.value(dump.width);
  w.value(dump.height);
  w.value(dump.viewport);
  w.value(dump.projection);
  w.value(dump.camera_valid);
  w.value(dump.samples);
  w.value(dump.bounces);
  w.value(dump.options);
  w.value(dump.rays);
  w.value(dump.trace_ms);
  w.value(static_cast<uint32_t>(dump.shapes.size()));
  for (const SceneDumpShape& shape : dump.shapes) {
    w.value(shape.triangle_count());
    w.bytes(shape.positions.data(), size_t{shape.triangle_count()} * 9 * sizeof(float));
  }
  w.value(static_cast<uint32_t>(dump.instances.size()));
  for (const SceneDumpInstance& instance : dump.instances) {
    w.value(instance.shape);
    w.value(instance.mask);
    w.value(instance.flags);
    w.value(instance.transform);
    w.value(instance.first_triangle);
    w.value(instance.triangle_count);
  }
  w.value(dump.triangle_count());
  w.bytes(dump.eye_triangles.data(), dump.triangle_count() * 9 * sizeof(float));
  w.value(static_cast<uint32_t>(dump.lights.size()));
  for (const SceneDumpLight& light : dump.lights) {
    w.value(light.position);
    w.value(light.radius);
    w.value(light.shadow_mask);
  }
  const bool flushed = w.ok() && std::fflush(file.get()) == 0;
  if (!flushed && error != nullptr) *error = "cannot write " + path;
  return flushed;
}

bool read_scene_dump(const std::string& path, SceneDump& dump, std::string* error) {
  auto fail = [&](const std::string& why) {
    if (error != nullptr) *error = path + ": " + why;
    return false;
  };
  File file(std::fopen(path.c_str(), "rb"));
  if (!file) return fail("cannot open");
  Reader r(file.get());
  char magic[8] = {};
  r.bytes(magic, sizeof magic);
  if (!r.ok() || std::memcmp(magic, kMagic, sizeof kMagic) != 0)
    return fail("not a glpt scene dump");
  if (r.value<uint32_t>() != SceneDump::kVersion) return fail("unsupported version");
  dump = SceneDump();
  dump.frame = r.value<uint64_t>();
  dump.width = r.value<uint32_t>();
  dump.height = r.value<uint32_t>();
  dump.viewport = r.value<std::array<int32_t, 4>>();
  dump.projection = r.value<std::array<float, 16>>();
  dump.camera_valid = r.value<uint32_t>();
  dump.samples = r.value<uint32_t>();
  dump.bounces = r.value<uint32_t>();
  dump.options = r.value<uint32_t>();
  dump.rays = r.value<uint64_t>();
  dump.trace_ms = r.value<double>();
  const uint32_t shapes = r.value<uint32_t>();
  if (!r.ok() || shapes > kMaxCount / 2) return fail("truncated header");
  dump.shapes.resize(shapes);
  for (SceneDumpShape& shape : dump.shapes)
    if (!r.floats(shape.positions, r.value<uint32_t>(), 9)) return fail("truncated shapes");
  const uint32_t instances = r.value<uint32_t>();
  if (!r.ok()) return fail("truncated instances");
  dump.instances.resize(instances);
  for (SceneDumpInstance& instance : dump.instances) {
    instance.shape = r.value<uint32_t>();
    instance.mask = r.value<uint32_t>();
    instance.flags = r.value<uint32_t>();
    instance.transform = r.value<std::array<float, 12>>();
    instance.first_triangle = r.value<uint64_t>();
    instance.triangle_count = r.value<uint32_t>();
    if (instance.shape >= shapes) r.fail();
  }
  if (!r.ok()) return fail("truncated or inconsistent instances");
  if (!r.floats(dump.eye_triangles, r.value<uint64_t>(), 9)) return fail("truncated triangles");
  for (const SceneDumpInstance& instance : dump.instances)
    if (instance.first_triangle + instance.triangle_count > dump.triangle_count())
      return fail("instance triangles out of range");
  const uint32_t lights = r.value<uint32_t>();
  if (!r.ok() || lights > kMaxCount / 2) return fail("truncated lights");
  dump.lights.resize(lights);
  for (SceneDumpLight& light : dump.lights) {
    light.position = r.value<std::array<float, 4>>();
    light.radius = r.value<float>();
    light.shadow_mask = r.value<uint32_t>();
  }
  if (!r.ok()) return fail("truncated lights");
  return true;
}

}  // namespace glpt::rt
