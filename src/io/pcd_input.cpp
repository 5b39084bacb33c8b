#include "io/pcd_input.h"

#include <pcl/PCLPointCloud2.h>
#include <pcl/common/io.h>
#include <pcl/console/print.h>
#include <pcl/io/pcd_io.h>

#include <algorithm>
#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <new>
#include <sstream>
#include <exception>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace floodplane::io {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& reason) { throw std::runtime_error(reason); }

// PCL's reader logs its own multi-line complaints; the reader's exception says what went
// wrong in one line, so PCL is silenced while it reads and restored after.
class QuietPcl {
 public:
  QuietPcl() : previous_(pcl::console::getVerbosityLevel()) { pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS); }
  ~QuietPcl() { pcl::console::setVerbosityLevel(previous_); }
  QuietPcl(const QuietPcl&) = delete;
  QuietPcl& operator=(const QuietPcl&) = delete;

 private:
  pcl::console::VERBOSITY_LEVEL previous_;
};

// PCL's reader trusts the sizes written in a binary file: a truncated binary_compressed file
// makes it read past the end of its memory map (a crash, not an error code). So the body's
// size is checked against the file's size here, from the header PCL has parsed, before PCL
// reads the body.
void checkBodySize(const std::string& path, std::uintmax_t file_size, int data_type, unsigned data_index,
                   const pcl::PCLPointCloud2& header) {
  const std::uint64_t body_size = std::uint64_t{header.width} * header.height * header.point_step;
  if (data_type == 1) {  // binary: the points, raw
    if (data_index + body_size > file_size) {
      fail("truncated PCD file: the header announces " + std::to_string(body_size) +
           " bytes of binary data, the file holds " + std::to_string(file_size - data_index));
    }
  } else if (data_type == 2) {  // binary_compressed: two uint32 sizes, then LZF data
    if (data_index + 8 > file_size) {
      fail("truncated PCD file: the compressed data is missing");
    }
    std::ifstream in(path, std::ios::binary);
    in.seekg(static_cast<std::streamoff>(data_index));
    std::uint32_t sizes[2] = {0, 0};
    in.read(reinterpret_cast<char*>(sizes), sizeof(sizes));
    if (!in) fail("cannot read the compressed data");
    const std::uint32_t compressed_size = sizes[0];
    const std::uint32_t uncompressed_size = sizes[1];
    if (data_index + 8 + std::uint64_t{compressed_size} > file_size) {
      fail("truncated PCD file: the header announces " + std::to_string(compressed_size) +
           " bytes of compressed data, the file holds " + std::to_string(file_size - data_index - 8));
    }
    if (uncompressed_size != body_size) {
      fail("corrupt PCD file: the compressed data unpacks to " + std::to_string(uncompressed_size) + " bytes, " +
           std::to_string(header.width) + " x " + std::to_string(header.height) + " points need " +
           std::to_string(body_size));
    }
  }
}

// A number of the header's SIZE, COUNT, WIDTH, HEIGHT or POINTS line: PCL reads it into an
// int with >>, which turns an overflowing or negative value into a huge size. So one that does
// not start with digits or exceeds INT_MAX is refused here.
std::uint64_t headerCount(const std::string& key, const std::string& word) {
  std::uint64_t value = 0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (error != std::errc() || value > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) {
    fail("corrupt PCD header: " + key + " value '" + word.substr(0, 24) + "' is not a count");
  }
  return value;
}

// What the header announces, as far as the size of the point buffer goes.
struct AnnouncedSize {
  std::size_t field_count = 0;
  std::vector<std::uint64_t> sizes;
  std::vector<std::uint64_t> counts;
  std::uint64_t width = 0;
  std::uint64_t height = 0;
  std::uint64_t points = 0;
};

// Refuses a body that cannot hold what the header announces, once its DATA line is reached.
void checkBody(const AnnouncedSize& header, const std::string& type, std::uint64_t body) {
  if (header.sizes.size() != header.field_count) return;  // PCL will say what is wrong
  std::vector<std::uint64_t> counts = header.counts;
  counts.resize(header.field_count, 1);
  std::uint64_t point_step = 0;
  std::uint64_t values = 0;  // per point
  for (std::size_t i = 0; i < header.field_count; ++i) {
    point_step += std::min<std::uint64_t>(header.sizes[i], 8) * counts[i];
    values += counts[i];
  }
  // PCL keeps a point's size in 32 bits; no real point needs a gigabyte.
  if (point_step > static_cast<std::uint64_t>(std::numeric_limits<int>::max())) {
    fail("corrupt PCD header: SIZE x COUNT gives points of " + std::to_string(point_step) + " bytes");
  }
  // PCL sizes the buffer from POINTS, and checks it against WIDTH x HEIGHT: the larger counts.
  const std::uint64_t points = std::max(header.points, header.width * header.height);
  // ASCII needs at least two characters (digit and separator) per value; LZF packs at most
  // about 100:1 (a 3-byte back-reference repeats up to 264 bytes).
  const std::uint64_t per_point_bound = type == "ascii" ? 2 * values : point_step;
  const std::uint64_t factor = type == "binary_compressed" ? 100 : 1;
  // Every count is below 2^31 and a header line holds at most 64 Ki fields, so the steps do
  // not overflow; the products are compared by division first. 2^40 bytes is no frame.
  const std::uint64_t step = std::max<std::uint64_t>({per_point_bound, point_step, 1});
  if (points > (std::uint64_t{1} << 40) / step || points * per_point_bound > body * factor) {
    fail("corrupt or truncated PCD file: the header announces " + std::to_string(points) + " points of " +
         std::to_string(point_step) + " bytes, the file's " + std::to_string(body) + " bytes of data cannot hold them");
  }
}

// PCL's readHeader allocates (and zero-fills) the whole point buffer the header announces
// before reading a byte of data, so a corrupt WIDTH, POINTS or COUNT line can ask for
// terabytes (std::bad_alloc) or, worse, for a few gigabytes that are granted and swap the
// machine. This reads the header's sizes itself and refuses a body that the file cannot hold;
// it only rejects, and leaves every other judgement of the header to PCL.
void checkAnnouncedSize(const std::string& path, std::uintmax_t file_size) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  AnnouncedSize header;
  // A header is a few hundred bytes; 64 KiB without DATA is not a header.
  while (in.tellg() < 65536 && std::getline(in, line)) {
    std::istringstream words(line);
    std::string key;
    words >> key;
    std::string word;
    if (key == "FIELDS") {
      while (words >> word) ++header.field_count;
    } else if (key == "SIZE") {
      while (words >> word) header.sizes.push_back(headerCount(key, word));
    } else if (key == "COUNT") {
      while (words >> word) header.counts.push_back(headerCount(key, word));
    } else if (key == "WIDTH" || key == "HEIGHT" || key == "POINTS") {
      if (!(words >> word)) continue;  // PCL will say what is wrong
      const std::uint64_t value = headerCount(key, word);
      (key == "WIDTH" ? header.width : key == "HEIGHT" ? header.height : header.points) = value;
    } else if (key == "DATA") {
      words >> word;
      const std::streamoff header_end = in.tellg();
      if (header_end < 0) return;
      checkBody(header, word, file_size - static_cast<std::uint64_t>(header_end));
      return;
    }
  }
}

// PCL parses the header line by line, each line overriding what an earlier one said (and
// lines after DATA are parsed as header too), and reads the body with the result: a SIZE line
// after TYPE leaves a float in a 1-byte slot, a SIZE or COUNT line after POINTS leaves a
// buffer smaller than the points, and PCL then writes past the buffer. So every field must
// fit in its point with the size of its type, and the buffer must hold the points, before
// PCL reads a byte of the body. (Found by fuzz_pcd_loader as heap corruption.)
void checkLayout(const pcl::PCLPointCloud2& cloud) {
  for (const pcl::PCLPointField& field : cloud.fields) {
    const std::uint64_t size = pcl::getFieldSize(field.datatype);
    if (size == 0 || field.count == 0) {
      fail("corrupt PCD header: field " + field.name.substr(0, 24) + " has no valid SIZE, TYPE and COUNT");
    }
    if (std::uint64_t{field.offset} + std::uint64_t{field.count} * size > cloud.point_step) {
      fail("corrupt PCD header: field " + field.name.substr(0, 24) +
           " does not fit in its point (SIZE, TYPE and COUNT disagree)");
    }
  }
  if (cloud.data.size() != std::uint64_t{cloud.width} * cloud.height * cloud.point_step) {
    fail("corrupt PCD header: WIDTH x HEIGHT points of " + std::to_string(cloud.point_step) +
         " bytes do not match the POINTS line");
  }
}

// The file as PCL's untyped cloud, with its sensor pose, after every check that has to come
// before PCL reads the body.
struct RawCloud {
  pcl::PCLPointCloud2 cloud;
  Eigen::Vector4f origin;
  Eigen::Quaternionf orientation;
};

RawCloud readRawCloud(const std::string& path) {
  std::error_code error;
  const std::uintmax_t file_size = fs::file_size(path, error);
  if (error) fail("cannot read file: " + error.message());
  if (file_size == 0) fail("empty file, not a PCD file");
  // PCL's reader says "cannot read header" for a file it cannot open; say why instead.
  if (!std::ifstream(path, std::ios::binary)) fail(std::string("cannot open file: ") + std::strerror(errno));

  checkAnnouncedSize(path, file_size);

  const QuietPcl quiet;
  pcl::PCDReader reader;
  RawCloud raw;
  int version = 0;
  int data_type = 0;
  unsigned data_index = 0;
  try {
    if (reader.readHeader(path, raw.cloud, raw.origin, raw.orientation, version, data_type, data_index) < 0) {
      fail("not a PCD file, or its header is invalid");
    }
    // PCL 1.13's read() dereferences the first field without checking that there is one.
    if (raw.cloud.fields.empty() || raw.cloud.point_step == 0) {
      fail("not a PCD file, or its header is invalid (no fields)");
    }
    if (std::uint64_t{raw.cloud.width} * raw.cloud.height == 0) {
      fail("the cloud has no points (" + std::to_string(raw.cloud.width) + " x " + std::to_string(raw.cloud.height) +
           ")");
    }
    if (data_index > file_size) fail("truncated PCD file: the header is incomplete");
    checkLayout(raw.cloud);
    checkBodySize(path, file_size, data_type, data_index, raw.cloud);
    if (reader.read(path, raw.cloud, raw.origin, raw.orientation, version) < 0) {
      fail("corrupt or truncated PCD file (PCL cannot read its data)");
    }
  } catch (const pcl::PCLException& e) {
    fail(std::string("corrupt PCD file: ") + e.what());
  } catch (const std::runtime_error&) {
    throw;  // this reader's own reasons
  } catch (const std::bad_alloc&) {
    fail("corrupt PCD file: its header announces more points than fit in memory");
  } catch (const std::exception& e) {
    // PCL's header parser indexes the words of a line with at() and converts them with
    // boost::lexical_cast: a line with too few words or a bad number throws
    // std::out_of_range or boost::bad_lexical_cast, not its own exception.
    fail(std::string("not a PCD file, or its header is invalid (") + e.what() + ")");
  }
  return raw;
}

const pcl::PCLPointField* findField(const pcl::PCLPointCloud2& cloud, const std::string& name) {
  for (const auto& field : cloud.fields) {
    if (field.name == name) return &field;
  }
  return nullptr;
}

// The fields the frame is made of; colour and label are null when the file has none (or
// none of a type read here).
struct FrameFields {
  const pcl::PCLPointField* x = nullptr;
  const pcl::PCLPointField* y = nullptr;
  const pcl::PCLPointField* z = nullptr;
  const pcl::PCLPointField* color = nullptr;
  const pcl::PCLPointField* label = nullptr;
};

// Checks that the cloud is an organized grid of 3-D points whose fields lie inside its points.
FrameFields checkedFields(const pcl::PCLPointCloud2& cloud) {
  for (const char* name : {"x", "y", "z"}) {
    const pcl::PCLPointField* field = findField(cloud, name);
    if (!field) fail("the cloud has no x y z fields (this method needs 3D points)");
    if (!(field->datatype == pcl::PCLPointField::FLOAT32 || field->datatype == pcl::PCLPointField::FLOAT64) ||
        field->count != 1) {
      fail(std::string("field ") + name + " is not a single float or double");
    }
  }
  if (cloud.height <= 1) {
    fail("unorganized cloud (" + std::to_string(cloud.width) + " x " + std::to_string(cloud.height) +
         "): this method needs an organized cloud (an image grid, height > 1)");
  }
  const std::size_t count = std::size_t{cloud.width} * cloud.height;
  if (cloud.data.size() < count * cloud.point_step) {
    fail("corrupt PCD file: " + std::to_string(cloud.data.size()) + " bytes of point data for " +
         std::to_string(count) + " points");
  }

  FrameFields fields{findField(cloud, "x"), findField(cloud, "y"), findField(cloud, "z"), findField(cloud, "rgb"),
                     findField(cloud, "label")};
  if (!fields.color) fields.color = findField(cloud, "rgba");
  // rgb is packed into 4 bytes whatever type the file declares (PCL writes F, others U).
  if (fields.color && !(fields.color->count == 1 && pcl::getFieldSize(fields.color->datatype) == 4)) {
    fields.color = nullptr;
  }
  if (fields.label && !(fields.label->count == 1 && fields.label->datatype == pcl::PCLPointField::UINT32)) {
    fields.label = nullptr;
  }
  for (const pcl::PCLPointField* field : {fields.x, fields.y, fields.z, fields.color, fields.label}) {
    if (field && field->offset + pcl::getFieldSize(field->datatype) > cloud.point_step) {
      fail("corrupt PCD file: field " + field->name + " lies outside the point");
    }
  }
  return fields;
}

// x, y, z may be stored as float or double (both occur in the wild); read either as float.
float readCoordinate(const std::uint8_t* point, const pcl::PCLPointField& field) {
  if (field.datatype == pcl::PCLPointField::FLOAT64) {
    double value;
    std::memcpy(&value, point + field.offset, sizeof(value));
    return static_cast<float>(value);
  }
  float value;
  std::memcpy(&value, point + field.offset, sizeof(value));
  return value;
}

std::uint32_t readUint32(const std::uint8_t* point, const pcl::PCLPointField& field) {
  std::uint32_t value;
  std::memcpy(&value, point + field.offset, sizeof(value));
  return value;
}

pcl::PointCloud<pcl::PointXYZ> xyzCloud(const RawCloud& raw, const FrameFields& fields) {
  const pcl::PCLPointCloud2& cloud = raw.cloud;
  pcl::PointCloud<pcl::PointXYZ> xyz;
  xyz.resize(cloud.width, cloud.height);
  xyz.sensor_origin_ = raw.origin;
  xyz.sensor_orientation_ = raw.orientation;
  bool dense = true;
  for (std::size_t i = 0; i < xyz.size(); ++i) {
    const std::uint8_t* point = cloud.data.data() + i * cloud.point_step;
    pcl::PointXYZ& p = xyz[i];
    p.x = readCoordinate(point, *fields.x);
    p.y = readCoordinate(point, *fields.y);
    p.z = readCoordinate(point, *fields.z);
    dense = dense && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
  }
  xyz.is_dense = dense;
  return xyz;
}

pcl::PointCloud<pcl::PointXYZRGB> xyzrgbCloud(const pcl::PointCloud<pcl::PointXYZ>& xyz,
                                              const pcl::PCLPointCloud2& cloud, const pcl::PCLPointField& color) {
  pcl::PointCloud<pcl::PointXYZRGB> xyzrgb;
  xyzrgb.resize(cloud.width, cloud.height);
  xyzrgb.sensor_origin_ = xyz.sensor_origin_;
  xyzrgb.sensor_orientation_ = xyz.sensor_orientation_;
  xyzrgb.is_dense = xyz.is_dense;
  for (std::size_t i = 0; i < xyzrgb.size(); ++i) {
    pcl::PointXYZRGB& p = xyzrgb[i];
    p.getVector3fMap() = xyz[i].getVector3fMap();
    p.rgba = readUint32(cloud.data.data() + i * cloud.point_step, color);
  }
  return xyzrgb;
}

std::vector<std::uint32_t> labelGrid(const pcl::PCLPointCloud2& cloud, const pcl::PCLPointField& label) {
  std::vector<std::uint32_t> labels(std::size_t{cloud.width} * cloud.height);
  for (std::size_t i = 0; i < labels.size(); ++i) {
    labels[i] = readUint32(cloud.data.data() + i * cloud.point_step, label);
  }
  return labels;
}

}  // namespace

InputFrame readPcdFrame(const std::string& path) {
  const RawCloud raw = readRawCloud(path);
  const FrameFields fields = checkedFields(raw.cloud);
  InputFrame frame;
  frame.xyz = xyzCloud(raw, fields);
  if (fields.color) frame.xyzrgb = xyzrgbCloud(frame.xyz, raw.cloud, *fields.color);
  if (fields.label) frame.labels = labelGrid(raw.cloud, *fields.label);
  return frame;
}

}  // namespace floodplane::io
