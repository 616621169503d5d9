// The direct PNG decoder (rdsf::decode_png) against cv::imdecode, the reference every read used before:
// the same pixels bit for bit on cv::imencode's files (its adaptive filters) and on files built here with
// each of the five row filters, and the same refusal (same message) of damaged files whose CRCs were
// made right again, so that only the zlib stream, the filter bytes or the sizes are wrong.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <libdeflate.h>
#include <opencv2/imgcodecs.hpp>

#include "rdsf/core/error.hpp"
#include "rdsf/frame/png_decoder.hpp"

namespace {

using Bytes = std::vector<unsigned char>;

void put_u32(Bytes& out, std::uint32_t v) {
  for (int s = 24; s >= 0; s -= 8) out.push_back(static_cast<unsigned char>(v >> s));
}

void put_chunk(Bytes& out, const char* type, const Bytes& data) {
  put_u32(out, static_cast<std::uint32_t>(data.size()));
  const std::size_t start = out.size();
  out.insert(out.end(), type, type + 4);
  out.insert(out.end(), data.begin(), data.end());
  put_u32(out, static_cast<std::uint32_t>(libdeflate_crc32(0, &out[start], data.size() + 4)));
}

// The PNG rows of `image` (RGB order, big-endian samples) each filtered with filter (row + shift) % 5, the
// straightforward way of the PNG specification.
// The filter of row y: shifts 0..4 cycle through the five filters (no two Paeth rows in a row); 5 is Paeth
// on every row; 6 mixes runs of 1, 2 and 3 Paeth rows with the others.
// 7 gives runs of 1, 2, ..., 9 Paeth rows, each followed by one row of another filter (runs of 2 to 4 are
// undone together as one wavefront, longer runs in several).
int filter_of(int y, int shift) {
  static const int kRuns[] = {4, 2, 4, 4, 1, 4, 4, 4, 0, 3};
  static const std::vector<int> kLongRuns = [] {
    std::vector<int> filters;
    for (int run = 1; run <= 9; ++run) {
      filters.insert(filters.end(), static_cast<std::size_t>(run), 4);
      filters.push_back(run % 4);
    }
    return filters;
  }();
  if (shift == 5) return 4;
  if (shift == 6) return kRuns[y % 10];
  if (shift == 7) return kLongRuns[static_cast<std::size_t>(y) % kLongRuns.size()];
  return (y + shift) % 5;
}

Bytes filtered_rows(const cv::Mat& image, int shift) {
  const int channels = image.channels();
  const int sample_bytes = image.depth() == CV_16U ? 2 : 1;
  const int bpp = channels * sample_bytes;
  const std::size_t row_bytes = static_cast<std::size_t>(image.cols) * bpp;
  Bytes out, previous(row_bytes, 0);
  for (int y = 0; y < image.rows; ++y) {
    Bytes row(row_bytes);
    for (int x = 0; x < image.cols; ++x) {
      for (int c = 0; c < channels; ++c) {
        const int source = channels >= 3 && c < 3 ? 2 - c : c;  // BGR(A) -> RGB(A)
        const std::uint32_t v = sample_bytes == 2 ? image.ptr<std::uint16_t>(y)[x * channels + source]
                                                  : image.ptr<std::uint8_t>(y)[x * channels + source];
        const std::size_t at = static_cast<std::size_t>(x) * bpp + c * sample_bytes;
        if (sample_bytes == 2) {
          row[at] = static_cast<unsigned char>(v >> 8);
          row[at + 1] = static_cast<unsigned char>(v);
        } else {
          row[at] = static_cast<unsigned char>(v);
        }
      }
    }
    const int filter = filter_of(y, shift);
    out.push_back(static_cast<unsigned char>(filter));
    for (std::size_t i = 0; i < row_bytes; ++i) {
      const int a = i >= static_cast<std::size_t>(bpp) ? row[i - bpp] : 0;
      const int b = previous[i];
      const int c = i >= static_cast<std::size_t>(bpp) ? previous[i - bpp] : 0;
      int predictor = 0;
      if (filter == 1) predictor = a;
      if (filter == 2) predictor = b;
      if (filter == 3) predictor = (a + b) / 2;
      if (filter == 4) {
        const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
        predictor = (pa <= pb && pa <= pc) ? a : (pb <= pc ? b : c);
      }
      out.push_back(static_cast<unsigned char>(row[i] - predictor));
    }
    previous = row;
  }
  return out;
}

Bytes zlib(const Bytes& raw) {
  libdeflate_compressor* compressor = libdeflate_alloc_compressor(6);
  Bytes out(libdeflate_zlib_compress_bound(compressor, raw.size()));
  out.resize(libdeflate_zlib_compress(compressor, raw.data(), raw.size(), out.data(), out.size()));
  libdeflate_free_compressor(compressor);
  return out;
}

// A PNG of `image` with hand-chosen filters, the zlib stream split over IDAT chunks of `idat_size` bytes.
Bytes build_png(const cv::Mat& image, int shift, std::size_t idat_size, const Bytes* rows = nullptr) {
  Bytes png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  Bytes header;
  put_u32(header, static_cast<std::uint32_t>(image.cols));
  put_u32(header, static_cast<std::uint32_t>(image.rows));
  const int channels = image.channels();
  header.push_back(image.depth() == CV_16U ? 16 : 8);
  header.push_back(channels == 1 ? 0 : (channels == 3 ? 2 : 6));
  header.insert(header.end(), {0, 0, 0});
  put_chunk(png, "IHDR", header);
  put_chunk(png, "tEXt", Bytes{'K', 0, 'v'});
  // Chunks the decoders read without changing the pixels (the real frames carry these).
  put_chunk(png, "gAMA", Bytes{0, 0, 0xb1, 0x8f});
  put_chunk(png, "bKGD", channels == 1 ? Bytes{0, 7} : Bytes{0, 1, 0, 2, 0, 3});
  const Bytes stream = zlib(rows ? *rows : filtered_rows(image, shift));
  for (std::size_t at = 0; at < stream.size(); at += idat_size) {
    put_chunk(png, "IDAT", Bytes(stream.begin() + at, stream.begin() + std::min(stream.size(), at + idat_size)));
  }
  put_chunk(png, "IEND", {});
  return png;
}

cv::Mat random_image(int rows, int cols, int type, bool smooth) {
  cv::Mat image(rows, cols, type);
  if (smooth) {  // gradients and steps, so that the filters and the zlib matches matter
    cv::Mat wide(rows, cols, CV_MAKETYPE(CV_32F, image.channels()));
    cv::randu(wide, 0, 255);
    for (int y = 0; y < rows; ++y) {
      auto* p = wide.ptr<float>(y);
      for (int i = 0; i < cols * image.channels(); ++i) p[i] = static_cast<float>((y * 7 + i * 3) % 251) + p[i] * 0.02f;
    }
    wide.convertTo(image, type, image.depth() == CV_16U ? 250.0 : 1.0);
  } else {
    cv::randu(image, 0, image.depth() == CV_16U ? 65536 : 256);
  }
  return image;
}

bool same(const cv::Mat& a, const cv::Mat& b) {
  return a.type() == b.type() && a.size() == b.size() && cv::norm(a, b, cv::NORM_INF) == 0;
}

// Both decoders on `png`: the same image, or the same error message.
void expect_same_decoding(const Bytes& png, const std::string& what) {
  std::string direct_error, reference_error;
  cv::Mat direct, reference;
  try {
    direct = rdsf::decode_png("x.png", png.data(), png.size());
  } catch (const rdsf::Error& e) {
    direct_error = e.what();
  }
  try {
    reference = rdsf::decode_png("x.png", png.data(), png.size(), rdsf::PngDecodeOptions{false});
  } catch (const rdsf::Error& e) {
    reference_error = e.what();
  }
  EXPECT_EQ(direct_error, reference_error) << what;
  if (direct_error.empty() && reference_error.empty()) {
    EXPECT_TRUE(same(direct, reference)) << what;
  }
}

const int kTypes[] = {CV_8UC1, CV_8UC3, CV_8UC4, CV_16UC1, CV_16UC3, CV_16UC4};

TEST(PngDecoder, SameAsImdecodeOnImencodeFiles) {
  for (const int type : kTypes) {
    for (const cv::Size size : {cv::Size(1, 1), cv::Size(7, 3), cv::Size(640, 480)}) {
      for (const bool smooth : {false, true}) {
        const cv::Mat image = random_image(size.height, size.width, type, smooth);
        Bytes png;
        ASSERT_TRUE(cv::imencode(".png", image, png));
        const cv::Mat decoded = rdsf::decode_png("x.png", png.data(), png.size());
        EXPECT_TRUE(same(decoded, image)) << "type " << type << " size " << size;
        EXPECT_TRUE(same(decoded, cv::imdecode(png, cv::IMREAD_UNCHANGED)));
      }
    }
  }
}

TEST(PngDecoder, EveryFilterTypeSameAsImdecode) {
  for (const int type : kTypes) {
    for (const cv::Size size : {cv::Size(1, 5), cv::Size(3, 11), cv::Size(64, 20)}) {
      const cv::Mat image = random_image(size.height, size.width, type, true);
      for (int shift = 0; shift < 5; ++shift) {
        const Bytes png = build_png(image, shift, shift == 0 ? 1U << 20 : 97);
        const cv::Mat decoded = rdsf::decode_png("x.png", png.data(), png.size());
        EXPECT_TRUE(same(decoded, image)) << "type " << type << " size " << size << " shift " << shift;
        EXPECT_TRUE(same(decoded, cv::imdecode(png, cv::IMREAD_UNCHANGED)));
      }
    }
  }
}

// Paeth's three-way choice and its ties (pa == pb, pb == pc: a before b before c) on samples from a
// four-value alphabet, where ties are common, with every filter, at widths on both sides of the
// vectorised Paeth path's bounds (it needs two pixels) and the row's end, where it reads past the pixel;
// with Paeth rows alone, in pairs and in odd runs (two Paeth rows are undone together), odd and even heights.
TEST(PngDecoder, PaethTiesAndRowEndsSameAsImdecode) {
  std::mt19937 rng(23);
  const int alphabet[] = {0, 1, 128, 255};
  for (const int type : kTypes) {
    for (const int cols : {1, 2, 3, 5, 8, 17, 33}) {
      cv::Mat image(cols % 2 ? 9 : 12, cols, type);
      const bool wide = image.depth() == CV_16U;
      for (int y = 0; y < image.rows; ++y) {
        for (int i = 0; i < cols * image.channels(); ++i) {
          const int v = alphabet[rng() % 4], w = alphabet[rng() % 4];
          if (wide) {
            image.ptr<std::uint16_t>(y)[i] = static_cast<std::uint16_t>(v << 8 | w);
          } else {
            image.ptr<std::uint8_t>(y)[i] = static_cast<std::uint8_t>(v);
          }
        }
      }
      for (int shift = 0; shift < 8; ++shift) {
        const Bytes png = build_png(image, shift, 1U << 20);
        const cv::Mat decoded = rdsf::decode_png("x.png", png.data(), png.size());
        EXPECT_TRUE(same(decoded, image)) << "type " << type << " cols " << cols << " shift " << shift;
        EXPECT_TRUE(same(decoded, cv::imdecode(png, cv::IMREAD_UNCHANGED)));
      }
    }
  }
}

// Runs of 1 to 9 Paeth rows (the decoder undoes runs of 2 to 4 rows as one wavefront, each row two pixels
// behind the one above) on noise, where all three of Paeth's choices occur, and on a four-value alphabet
// (ties), at widths shorter than the wavefront's start-up (a row starts 2 pixels after the one above) and
// a frame's, every 8- and 16-bit type; the rows of each run start at each place of the pattern once.
TEST(PngDecoder, PaethRunsOfEveryLengthSameAsImdecode) {
  std::mt19937 rng(36);
  const int alphabet[] = {0, 1, 128, 255};
  for (const int type : kTypes) {
    for (const int cols : {1, 2, 3, 4, 5, 6, 7, 9, 640}) {
      for (const bool ties : {false, true}) {
        cv::Mat image(54, cols, type);
        const bool wide = image.depth() == CV_16U;
        for (int y = 0; y < image.rows; ++y) {
          for (int i = 0; i < cols * image.channels(); ++i) {
            const unsigned v = ties ? static_cast<unsigned>(alphabet[rng() % 4]) : rng() % 256;
            const unsigned w = ties ? static_cast<unsigned>(alphabet[rng() % 4]) : rng() % 256;
            if (wide) {
              image.ptr<std::uint16_t>(y)[i] = static_cast<std::uint16_t>(v << 8 | w);
            } else {
              image.ptr<std::uint8_t>(y)[i] = static_cast<std::uint8_t>(v);
            }
          }
        }
        const Bytes png = build_png(image, 7, 1U << 20);
        const cv::Mat decoded = rdsf::decode_png("x.png", png.data(), png.size());
        EXPECT_TRUE(same(decoded, image)) << "type " << type << " cols " << cols << " ties " << ties;
        EXPECT_TRUE(same(decoded, cv::imdecode(png, cv::IMREAD_UNCHANGED)));
      }
    }
  }
}

TEST(PngDecoder, DamagedStreamsRefusedAsImdecodeRefusesThem) {
  std::mt19937 rng(7);
  const cv::Mat image = random_image(24, 32, CV_16UC1, true);
  const Bytes good = build_png(image, 0, 1U << 20);
  // The one IDAT chunk: after the signature, IHDR (25 bytes), tEXt (15), gAMA (16) and bKGD (14 for grey).
  const std::size_t idat = 8 + 25 + 15 + 16 + 14;
  const std::size_t length = (std::size_t{good[idat]} << 24) | (good[idat + 1] << 16) | (good[idat + 2] << 8) | good[idat + 3];
  ASSERT_EQ(std::string(good.begin() + idat + 4, good.begin() + idat + 8), "IDAT");
  const auto fix_crc = [&](Bytes& png, std::size_t chunk_length) {
    const auto crc = static_cast<std::uint32_t>(libdeflate_crc32(0, &png[idat + 4], chunk_length + 4));
    for (int k = 0; k < 4; ++k) png[idat + 8 + chunk_length + k] = static_cast<unsigned char>(crc >> (24 - 8 * k));
  };
  int refused = 0;
  for (int trial = 0; trial < 300; ++trial) {
    Bytes png = good;
    const std::size_t at = idat + 8 + rng() % length;
    png[at] = static_cast<unsigned char>(png[at] ^ (1U << (rng() % 8)));
    fix_crc(png, length);
    expect_same_decoding(png, "bit flip at " + std::to_string(at));
    try {
      rdsf::decode_png("x.png", png.data(), png.size());
    } catch (const rdsf::Error&) {
      ++refused;
    }
  }
  EXPECT_GT(refused, 250);  // the Adler-32 of the stream catches nearly every flip
  // The stream cut short, inside a chunk whose length and CRC say so.
  for (const std::size_t keep : {std::size_t{2}, length / 2, length - 1}) {
    Bytes png(good.begin(), good.begin() + idat + 8 + keep);
    Bytes tail(good.begin() + idat + 8 + length, good.end());
    png.insert(png.end(), tail.begin(), tail.end());
    for (int k = 0; k < 4; ++k) png[idat + k] = static_cast<unsigned char>(keep >> (24 - 8 * k));
    fix_crc(png, keep);
    expect_same_decoding(png, "stream cut to " + std::to_string(keep));
  }
}

TEST(PngDecoder, BadFilterTypeAndWrongSizeRefused) {
  const cv::Mat image = random_image(6, 9, CV_8UC3, true);
  Bytes rows = filtered_rows(image, 0);
  rows[(9 * 3 + 1) * 2] = 5;  // the third row's filter byte
  expect_same_decoding(build_png(image, 0, 1U << 20, &rows), "filter type 5");
  const Bytes split = build_png(image, 0, 64, &rows);
  EXPECT_THROW(rdsf::decode_png("x.png", split.data(), split.size()), rdsf::Error);
  Bytes short_rows = filtered_rows(image, 1);
  short_rows.resize(short_rows.size() - 3);
  expect_same_decoding(build_png(image, 0, 1U << 20, &short_rows), "too little image data");
  Bytes long_rows = filtered_rows(image, 2);
  long_rows.insert(long_rows.end(), 40, 0);
  expect_same_decoding(build_png(image, 0, 1U << 20, &long_rows), "too much image data");
}

TEST(PngDecoder, RealFramesSameAsImdecode) {
  const std::filesystem::path real = std::filesystem::path(RDSF_SOURCE_DIR).parent_path() / "shared/realdata";
  if (!std::filesystem::is_directory(real)) GTEST_SKIP() << "no ../shared/realdata here";
  int compared = 0;
  for (const auto& group : {"people", "empty"}) {
    if (!std::filesystem::is_directory(real / group)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(real / group)) {
      if (entry.path().extension() != ".png") continue;
      const cv::Mat direct = rdsf::read_png_file(entry.path().string());
      const cv::Mat reference = cv::imread(entry.path().string(), cv::IMREAD_UNCHANGED);
      EXPECT_TRUE(same(direct, reference)) << entry.path();
      ++compared;
    }
  }
  EXPECT_GT(compared, 0);
}

}  // namespace
