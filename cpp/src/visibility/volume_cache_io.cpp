// Binary VV files for the on-disk cache, and the cache key of a VV's inputs.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <thread>
#include <type_traits>

#include "vistrack/error.hpp"
#include "vistrack/limits.hpp"
#include "vistrack/visibility.hpp"

namespace vistrack {
namespace {

constexpr char kMagic[8] = {'V', 'I', 'S', 'T', 'R', 'K', 'V', 'V'};
constexpr std::uint64_t kFnvOffset = 14695981039346656037ULL;
constexpr std::uint64_t kFnvPrime = 1099511628211ULL;

bool host_is_little_endian() {
  const std::uint32_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

// Appends scalars as little-endian bytes.
class Writer {
 public:
  template <class T>
  void put(T value) {
    static_assert(std::is_arithmetic_v<T>);
    put_array(&value, 1);
  }
  template <class T>
  void put_array(const T* values, std::size_t count) {
    static_assert(std::is_arithmetic_v<T>);
    const std::size_t start = bytes_.size();
    bytes_.resize(start + count * sizeof(T));
    if (count > 0) std::memcpy(bytes_.data() + start, values, count * sizeof(T));
    if (!host_is_little_endian())
      for (std::size_t k = 0; k < count; ++k) {
        char* p = bytes_.data() + start + k * sizeof(T);
        std::reverse(p, p + sizeof(T));
      }
  }
  void put_bytes(const char* data, std::size_t count) { bytes_.insert(bytes_.end(), data, data + count); }
  std::vector<char>& bytes() { return bytes_; }

 private:
  std::vector<char> bytes_;
};

// Reads little-endian scalars; throws Error naming the file on a short read.
class Reader {
 public:
  Reader(const std::vector<char>& bytes, std::size_t end, const std::string& path)
      : bytes_(bytes), end_(end), path_(path) {}
  template <class T>
  T get() {
    T value{};
    get_array(&value, 1);
    return value;
  }
  template <class T>
  void get_array(T* values, std::size_t count) {
    static_assert(std::is_arithmetic_v<T>);
    require_bytes(count, sizeof(T));
    if (count > 0) std::memcpy(values, bytes_.data() + at_, count * sizeof(T));
    if (!host_is_little_endian())
      for (std::size_t k = 0; k < count; ++k) {
        auto* p = reinterpret_cast<char*>(values + k);
        std::reverse(p, p + sizeof(T));
      }
    at_ += count * sizeof(T);
  }
  // Checks that `count` items of `size` bytes remain before allocating room for them.
  void require_bytes(std::size_t count, std::size_t size) const {
    if (count > (end_ - at_) / size) fail("truncated or corrupt (a count runs past the end)");
  }
  std::size_t position() const { return at_; }
  [[noreturn]] void fail(const std::string& reason) const {
    throw Error("VV cache file '" + path_ + "': " + reason);
  }

 private:
  const std::vector<char>& bytes_;
  std::size_t end_;
  const std::string& path_;
  std::size_t at_ = 0;
};

// FNV-1a over 8-byte little-endian words (8x fewer multiplies than per byte; files are MBs).
std::uint64_t checksum(const char* data, std::size_t size) {
  std::uint64_t h = kFnvOffset;
  std::size_t k = 0;
  for (; k + 8 <= size; k += 8) {
    std::uint64_t word = 0;
    for (int b = 0; b < 8; ++b) word |= std::uint64_t(static_cast<unsigned char>(data[k + std::size_t(b)])) << (8 * b);
    h = (h ^ word) * kFnvPrime;
  }
  for (; k < size; ++k) h = (h ^ static_cast<unsigned char>(data[k])) * kFnvPrime;
  return h;
}

// FNV-1a, byte by byte, of a 64-bit value taken least significant byte first (host independent).
void hash_word(std::uint64_t& h, std::uint64_t word) {
  for (int b = 0; b < 8; ++b) h = (h ^ ((word >> (8 * b)) & 0xffU)) * kFnvPrime;
}

std::uint64_t bits_of(double value) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}

// A name no other thread or process writing the same file will pick.
std::string temporary_path(const std::string& path) {
  const auto thread = std::hash<std::thread::id>{}(std::this_thread::get_id());
  const auto now = std::chrono::steady_clock::now().time_since_epoch().count();
  return path + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(thread) + "." + std::to_string(now);
}

}  // namespace

void write_volume_file(const VisibilityVolume& vv, const std::string& path) {
  detail::require_mesh(vv, "vv");
  const std::size_t cells = vv.grid.num_corners();
  if (vv.near.size() != cells || vv.far.size() != cells)
    detail::fail_field("vv.near.size()", vv.near.size(), "differs from the grid's corner count " + detail::to_text(cells));
  Writer out;
  out.put_bytes(kMagic, sizeof kMagic);
  out.put(kVolumeFileVersion);
  out.put_array(vv.poi.data(), 3);
  out.put(vv.d_max);
  out.put(std::int32_t(vv.altitude_band ? 1 : 0));
  out.put(vv.altitude_band ? vv.altitude_band->first : 0.0);
  out.put(vv.altitude_band ? vv.altitude_band->second : 0.0);
  out.put(std::int32_t(vv.grid.num_elevation));
  out.put(std::int32_t(vv.grid.num_azimuth));
  out.put_array(vv.near.data(), cells);
  out.put_array(vv.far.data(), cells);
  out.put(std::uint64_t(vv.mesh.vertices.rows()));
  out.put_array(vv.mesh.vertices.data(), std::size_t(vv.mesh.vertices.size()));  // row-major x, y, z
  out.put(std::uint64_t(vv.mesh.faces.rows()));
  out.put_array(vv.mesh.faces.data(), std::size_t(vv.mesh.faces.size()));
  out.put(vv.volume);
  out.put(std::uint64_t(vv.mesh_row_sines.size()));
  out.put_array(vv.mesh_row_sines.data(), vv.mesh_row_sines.size());
  out.put(std::uint64_t(vv.mesh_triangle_faces.size()));
  out.put_array(vv.mesh_triangle_faces.data(), vv.mesh_triangle_faces.size());
  out.put(checksum(out.bytes().data(), out.bytes().size()));

  const std::string temporary = temporary_path(path);
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    file.write(out.bytes().data(), std::streamsize(out.bytes().size()));
    file.close();
    if (!file) {
      std::remove(temporary.c_str());
      throw Error("VV cache file '" + path + "': cannot write '" + temporary + "'");
    }
  }
  std::error_code error;
  std::filesystem::rename(temporary, path, error);  // atomic replace on POSIX
  if (error) {
    std::remove(temporary.c_str());
    throw Error("VV cache file '" + path + "': cannot rename the temporary file: " + error.message());
  }
}

std::optional<VisibilityVolume> read_volume_file(const std::string& path) {
  std::error_code missing;
  if (!std::filesystem::exists(path, missing)) return std::nullopt;
  require_regular_file(path, "VV file", "VV");
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  if (!file) throw Error("VV cache file '" + path + "': cannot be opened for reading");
  const std::streamoff size = file.tellg();
  if (size < 0) throw Error("VV cache file '" + path + "': cannot be read");
  // A 0.1-degree VV (the finest grid) takes about 400 MB.
  if (size > (std::streamoff(1) << 32)) throw Error("VV cache file '" + path + "': larger than 4 GiB, not a VV file");
  std::vector<char> bytes(static_cast<std::size_t>(size));
  file.seekg(0);
  file.read(bytes.data(), size);
  if (!file) throw Error("VV cache file '" + path + "': cannot be read");

  const std::size_t trailer = sizeof(std::uint64_t);
  if (bytes.size() < sizeof kMagic + sizeof(std::uint32_t) + trailer ||
      std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    throw Error("VV cache file '" + path + "': not a vistrack VV file (bad magic or too short)");
  const std::size_t body = bytes.size() - trailer;
  Reader payload(bytes, body, path);
  char magic[sizeof kMagic];
  payload.get_array(magic, sizeof magic);
  const auto version = payload.get<std::uint32_t>();
  if (version < kOldestReadableVolumeFileVersion || version > kVolumeFileVersion)
    payload.fail("format version " + std::to_string(version) + ", this build reads versions " +
                 std::to_string(kOldestReadableVolumeFileVersion) + " to " + std::to_string(kVolumeFileVersion) +
                 (version == 3 ? " (version 3 kept intervals per cell; recompute the VV)" : ""));
  std::uint64_t stored = 0;
  for (std::size_t b = 0; b < trailer; ++b)
    stored |= std::uint64_t(static_cast<unsigned char>(bytes[body + b])) << (8 * b);
  if (stored != checksum(bytes.data(), body)) payload.fail("checksum mismatch (truncated or corrupt)");

  VisibilityVolume vv;
  payload.get_array(vv.poi.data(), 3);
  vv.d_max = payload.get<double>();
  const auto has_band = payload.get<std::int32_t>();
  const auto h_lo = payload.get<double>();
  const auto h_hi = payload.get<double>();
  if (has_band != 0 && has_band != 1) payload.fail("band flag " + std::to_string(has_band));
  if (has_band == 1) vv.altitude_band = std::make_pair(h_lo, h_hi);
  vv.grid.num_elevation = payload.get<std::int32_t>();
  vv.grid.num_azimuth = payload.get<std::int32_t>();
  if (vv.grid.num_elevation <= 0 || vv.grid.num_azimuth <= 0) payload.fail("grid size not positive");
  const std::size_t cells = vv.grid.num_corners();
  payload.require_bytes(cells, 2 * sizeof(double));
  vv.near.resize(cells);
  vv.far.resize(cells);
  payload.get_array(vv.near.data(), cells);
  payload.get_array(vv.far.data(), cells);
  const auto num_vertices = payload.get<std::uint64_t>();
  payload.require_bytes(num_vertices, 3 * sizeof(double));
  vv.mesh.vertices.resize(Eigen::Index(num_vertices), 3);
  payload.get_array(vv.mesh.vertices.data(), std::size_t(num_vertices) * 3);
  const auto num_faces = payload.get<std::uint64_t>();
  payload.require_bytes(num_faces, 3 * sizeof(std::int32_t));
  vv.mesh.faces.resize(Eigen::Index(num_faces), 3);
  payload.get_array(vv.mesh.faces.data(), std::size_t(num_faces) * 3);
  vv.volume = payload.get<double>();
  const auto num_rows = payload.get<std::uint64_t>();
  payload.require_bytes(num_rows, sizeof(double));
  vv.mesh_row_sines.resize(std::size_t(num_rows));
  payload.get_array(vv.mesh_row_sines.data(), vv.mesh_row_sines.size());
  const auto num_slots = payload.get<std::uint64_t>();
  payload.require_bytes(num_slots, sizeof(std::int32_t));
  vv.mesh_triangle_faces.resize(std::size_t(num_slots));
  payload.get_array(vv.mesh_triangle_faces.data(), vv.mesh_triangle_faces.size());
  if (payload.position() != body) payload.fail("unexpected bytes after the triangle faces");
  if (vv.mesh.faces.size() > 0 &&
      (vv.mesh.faces.minCoeff() < 0 || std::uint64_t(vv.mesh.faces.maxCoeff()) >= num_vertices))
    payload.fail("a face index is out of range");
  if (!std::is_sorted(vv.mesh_triangle_faces.begin(), vv.mesh_triangle_faces.end()) ||
      (!vv.mesh_triangle_faces.empty() &&
       (vv.mesh_triangle_faces.front() != 0 || std::uint64_t(vv.mesh_triangle_faces.back()) != num_faces)))
    payload.fail("the triangle face ranges do not cover the faces in order");
  validate_volume(vv, "VV cache file '" + path + "'");
  return vv;
}

void validate_volume(const VisibilityVolume& vv, const std::string& where) {
  const auto fail = [&](const std::string& field, const std::string& value, const std::string& reason) {
    throw Error(where + ": " + field + " = " + value + ": " + reason);
  };
  const auto check = [&](const auto& require, double value, const std::string& field) {
    try {
      require(value, field);
    } catch (const Error& error) {
      throw Error(where + ": " + error.what());
    }
  };
  for (int k = 0; k < 3; ++k) check(require_coordinate, vv.poi[k], "poi[" + std::to_string(k) + "]");
  check(require_length, vv.d_max, "d_max");
  if (vv.altitude_band) {
    check(require_coordinate, vv.altitude_band->first, "altitude_band[0]");
    check(require_coordinate, vv.altitude_band->second, "altitude_band[1]");
    if (!(vv.altitude_band->first < vv.altitude_band->second))
      fail("altitude_band", detail::to_text(vv.altitude_band->first) + ", " + detail::to_text(vv.altitude_band->second),
           "h_lo must be below h_hi");
  }
  // The grid must be one DirectionGrid::from_resolution makes (resolution in [0.1, 30] degrees).
  const DirectionGrid& grid = vv.grid;
  const std::string grid_text = std::to_string(grid.num_elevation) + "x" + std::to_string(grid.num_azimuth);
  if (grid.num_azimuth < 12 || grid.num_azimuth > 3600) fail("grid", grid_text, "not a grid of 0.1 to 30 degrees");
  const DirectionGrid expected = DirectionGrid::from_resolution(360.0 / grid.num_azimuth);
  if (expected.num_elevation != grid.num_elevation || expected.num_azimuth != grid.num_azimuth)
    fail("grid", grid_text, "not a grid DirectionGrid.from_resolution makes");
  if (vv.near.size() != grid.num_corners() || vv.far.size() != grid.num_corners())
    fail("near", std::to_string(vv.near.size()) + " intervals", "must have one interval per grid corner");
  const double reach = vv.d_max * (1.0 + 1e-9);
  for (std::size_t k = 0; k < grid.num_corners(); ++k)
    if (!(vv.near[k] >= 0.0 && vv.near[k] <= reach && vv.far[k] >= 0.0 && vv.far[k] <= reach))
      fail("near/far[" + std::to_string(k) + "]", detail::to_text(vv.near[k]) + ", " + detail::to_text(vv.far[k]),
           "a visible interval lies in [0, d_max]");
  const Points3& v = vv.mesh.vertices;
  for (Eigen::Index i = 0; i < v.rows(); ++i)
    for (int k = 0; k < 3; ++k)
      check(require_coordinate, v(i, k), "vertices[" + std::to_string(i) + "][" + std::to_string(k) + "]");
  const Faces& f = vv.mesh.faces;
  if (f.size() > 0 && (f.minCoeff() < 0 || f.maxCoeff() >= v.rows()))
    fail("faces", "index " + std::to_string(f.minCoeff() < 0 ? f.minCoeff() : f.maxCoeff()),
         "vertex index out of range [0, " + std::to_string(v.rows()) + ")");
  // The volume a mesh of radius d_max can hold (the ball), with room for rounding.
  const double ball = 4.2 * vv.d_max * vv.d_max * vv.d_max;
  if (!(vv.volume >= -1e-9 * ball && vv.volume <= ball)) fail("volume", detail::to_text(vv.volume), "not in [0, 4/3 pi d_max^3]");
  for (std::size_t k = 0; k < vv.mesh_row_sines.size(); ++k)
    if (!(vv.mesh_row_sines[k] >= -1.0 && vv.mesh_row_sines[k] <= 1.0) ||
        (k > 0 && !(vv.mesh_row_sines[k] > vv.mesh_row_sines[k - 1])))
      fail("mesh_row_sines[" + std::to_string(k) + "]", detail::to_text(vv.mesh_row_sines[k]),
           "row sines increase within [-1, 1]");
  if (!vv.mesh_triangle_faces.empty() &&
      vv.mesh_triangle_faces.size() != 2 * (vv.mesh_row_sines.size() - 1) * std::size_t(grid.num_azimuth) + 1)
    fail("mesh_triangle_faces", std::to_string(vv.mesh_triangle_faces.size()) + " entries",
         "one per triangle slot of the mesh rows, plus one");
}

std::uint64_t volume_cache_key(std::uint64_t environment_fingerprint, const Vec3& g, double d_max,
                               const std::optional<std::pair<double, double>>& altitude_band,
                               double resolution_deg) {
  std::uint64_t h = kFnvOffset;
  hash_word(h, kVolumeFileVersion);
  hash_word(h, environment_fingerprint);
  for (int axis = 0; axis < 3; ++axis) hash_word(h, bits_of(g[axis]));
  hash_word(h, bits_of(d_max));
  hash_word(h, altitude_band ? 1 : 0);
  if (altitude_band) {
    hash_word(h, bits_of(altitude_band->first));
    hash_word(h, bits_of(altitude_band->second));
  }
  hash_word(h, bits_of(resolution_deg));
  return h;
}

std::string volume_cache_file_name(std::uint64_t key) {
  char name[32];
  std::snprintf(name, sizeof name, "vv-%016llx.bin", static_cast<unsigned long long>(key));
  return name;
}

}  // namespace vistrack
