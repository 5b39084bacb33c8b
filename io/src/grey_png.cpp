// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "floodplane/io/grey_png.h"

#include <png.h>

#include <algorithm>
#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace floodplane::io {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& reason) { throw std::runtime_error(reason); }

// Deflate packs at most about 1032:1, so a file of n bytes holds at most about 1032 n bytes of
// pixels: a header announcing more is corrupt, and is refused before anything is allocated.
constexpr std::uint64_t kMaxDeflateRatio = 1032;
// libpng's own default limit is a million pixels a side; depth cameras have a few thousand.
constexpr png_uint_32 kMaxSide = 1u << 16;

// libpng reports errors by longjmp to the setjmp in decode; the message is kept here so
// that the C++ exception can say it. No C++ object with a destructor lives in a frame that
// the longjmp skips: only libpng's C frames sit between the two.
struct ErrorSink {
  char message[200] = "";
};

void onError(png_structp png, png_const_charp message) {
  auto* sink = static_cast<ErrorSink*>(png_get_error_ptr(png));
  std::snprintf(sink->message, sizeof(sink->message), "%s", message);
  png_longjmp(png, 1);
}

// Warnings (an unknown chunk, a bad sRGB profile) do not stop the read and are not printed.
void onWarning(png_structp, png_const_charp) {}

// Owns the FILE and libpng's structures, so they are freed however the read ends.
class PngReader {
 public:
  explicit PngReader(const std::string& path) : file_(std::fopen(path.c_str(), "rb")) {
    if (!file_) fail(std::string("cannot open file: ") + std::strerror(errno));
  }
  ~PngReader() {
    if (png_) png_destroy_read_struct(&png_, info_ ? &info_ : nullptr, nullptr);
    std::fclose(file_);
  }
  PngReader(const PngReader&) = delete;
  PngReader& operator=(const PngReader&) = delete;

  FILE* file() const { return file_; }
  png_structp png() const { return png_; }
  png_infop info() const { return info_; }

  void create(ErrorSink& sink) {
    png_ = png_create_read_struct(PNG_LIBPNG_VER_STRING, &sink, onError, onWarning);
    if (!png_) fail("out of memory reading the PNG file");
    info_ = png_create_info_struct(png_);
    if (!info_) fail("out of memory reading the PNG file");
  }

 private:
  FILE* file_ = nullptr;
  png_structp png_ = nullptr;
  png_infop info_ = nullptr;
};

void checkSignature(FILE* file) {
  png_byte signature[8] = {};
  if (std::fread(signature, 1, sizeof(signature), file) != sizeof(signature) ||
      png_sig_cmp(signature, 0, sizeof(signature)) != 0) {
    fail("not a PNG file");
  }
}

// What the header says.
struct Header {
  png_uint_32 width = 0;
  png_uint_32 height = 0;
  int bit_depth = 0;
  int color_type = 0;
};

// Why the image is not a `what` (one grey channel of 16 bits, or 8 with `accept_8_bit`), or
// corrupt; empty when it is fine.
std::string checkGreyFormat(const Header& header, std::uintmax_t file_size, const std::string& what,
                            bool accept_8_bit) {
  const std::string not_one = "not a " + what + ": ";
  if (header.color_type & PNG_COLOR_MASK_PALETTE) return not_one + "a palette (colour) PNG";
  if (header.color_type & PNG_COLOR_MASK_COLOR) {
    return not_one + "a colour PNG (a " + what + " has one grey channel)";
  }
  if (header.color_type & PNG_COLOR_MASK_ALPHA) return not_one + "a PNG with an alpha channel";
  if (header.bit_depth != 16 && !(accept_8_bit && header.bit_depth == 8)) {
    return not_one + std::to_string(header.bit_depth) + " bits per pixel (a " + what + " has " +
           (accept_8_bit ? "8 or 16)" : "16)");
  }
  const std::uint64_t bytes_per_sample = header.bit_depth == 16 ? 2 : 1;
  const std::uint64_t pixel_bytes = (std::uint64_t{header.width} * bytes_per_sample + 1) * header.height;
  if (header.width > kMaxSide || header.height > kMaxSide || pixel_bytes > kMaxDeflateRatio * file_size) {
    return "corrupt PNG file: its header announces " + std::to_string(header.width) + " x " +
           std::to_string(header.height) + " pixels, more than its " + std::to_string(file_size) + " bytes can hold";
  }
  return {};
}

// The libpng calls, between setjmp and the end of the read: the samples into `bytes`, rows
// packed, 16-bit ones in the machine's byte order. Returns false when libpng failed (its
// message is in the reader's ErrorSink); `problem` is set when the file is a PNG but not the
// image wanted. Every variable written here and read after a longjmp lives outside this
// function.
bool decode(PngReader& reader, std::uintmax_t file_size, const std::string& what, bool accept_8_bit, Header& header,
            std::string& problem, std::vector<std::uint8_t>& bytes, std::vector<png_bytep>& rows) {
  png_structp png = reader.png();
  png_infop info = reader.info();
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_user_limits(png, kMaxSide, kMaxSide);
  png_init_io(png, reader.file());
  png_set_sig_bytes(png, 8);
  png_read_info(png, info);
  header.width = png_get_image_width(png, info);
  header.height = png_get_image_height(png, info);
  header.bit_depth = png_get_bit_depth(png, info);
  header.color_type = png_get_color_type(png, info);
  problem = checkGreyFormat(header, file_size, what, accept_8_bit);
  if (!problem.empty()) return true;
  // PNG stores 16-bit samples big-endian; the image is wanted in the machine's order.
  const std::uint16_t probe = 1;
  if (header.bit_depth == 16 && *reinterpret_cast<const std::uint8_t*>(&probe) == 1) png_set_swap(png);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  const std::size_t row_bytes = std::size_t{header.width} * (header.bit_depth == 16 ? 2 : 1);
  bytes.resize(row_bytes * header.height);
  rows.resize(header.height);
  for (png_uint_32 y = 0; y < header.height; ++y) rows[y] = bytes.data() + std::size_t{y} * row_bytes;
  png_read_image(png, rows.data());
  png_read_end(png, nullptr);
  return true;
}

}  // namespace

GreyImage readGreyPng(const std::string& path, const std::string& what, bool accept_8_bit) {
  std::error_code error;
  const std::uintmax_t file_size = fs::file_size(path, error);
  if (error) fail("cannot read file: " + error.message());
  PngReader reader(path);
  checkSignature(reader.file());
  ErrorSink sink;
  reader.create(sink);
  Header header;
  std::string problem;
  std::vector<std::uint8_t> bytes;
  std::vector<png_bytep> rows;
  if (!decode(reader, file_size, what, accept_8_bit, header, problem, bytes, rows)) {
    fail(std::string("corrupt or truncated PNG file: ") + sink.message);
  }
  if (!problem.empty()) fail(problem);
  GreyImage image;
  image.width = static_cast<int>(header.width);
  image.height = static_cast<int>(header.height);
  image.bits = header.bit_depth;
  image.values.resize(std::size_t{header.width} * header.height);
  if (header.bit_depth == 16) {
    std::memcpy(image.values.data(), bytes.data(), bytes.size());
  } else {
    std::copy(bytes.begin(), bytes.end(), image.values.begin());
  }
  return image;
}

}  // namespace floodplane::io
