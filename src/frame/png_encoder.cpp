#include "rdsf/frame/png_encoder.hpp"

#include <libdeflate.h>
#include <zlib.h>
#ifdef __SSE2__
#include <emmintrin.h>
#endif

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>

#include "rdsf/core/error.hpp"
#include "rdsf/frame/image_codecs.hpp"

namespace rdsf {
namespace {

constexpr std::size_t kIdatBytes = 8192;           // libpng's PNG_ZBUF_SIZE: the size of every IDAT but the last
constexpr std::size_t kSmallWindowFrom = 16384;    // libpng shrinks zlib's window at or below this data size

// v big-endian at o[0..3].
void store32(unsigned char* o, std::uint32_t v) {
  o[0] = static_cast<unsigned char>(v >> 24);
  o[1] = static_cast<unsigned char>(v >> 16);
  o[2] = static_cast<unsigned char>(v >> 8);
  o[3] = static_cast<unsigned char>(v);
}

void put32(std::vector<unsigned char>& out, std::uint32_t v) {
  unsigned char bytes[4];
  store32(bytes, v);
  out.insert(out.end(), bytes, bytes + 4);
}

// length, type, data, CRC-32 of type and data.
void put_chunk(std::vector<unsigned char>& out, const char* type, const unsigned char* data, std::size_t size) {
  put32(out, static_cast<std::uint32_t>(size));
  const std::size_t type_at = out.size();
  out.insert(out.end(), type, type + 4);
  if (size > 0) out.insert(out.end(), data, data + size);
  put32(out, static_cast<std::uint32_t>(libdeflate_crc32(0, out.data() + type_at, size + 4)));
}

// One image row to PNG order: 16-bit samples big-endian, BGR(A) to RGB(A).
void to_png_order(const unsigned char* in, unsigned char* out, int width, int channels, int bytes_per_sample) {
  if (bytes_per_sample == 1) {
    if (channels == 1) {
      std::memcpy(out, in, static_cast<std::size_t>(width));
      return;
    }
    for (int x = 0; x < width; ++x, in += channels, out += channels) {
      out[0] = in[2];
      out[1] = in[1];
      out[2] = in[0];
      if (channels == 4) out[3] = in[3];
    }
    return;
  }
  const auto* s = reinterpret_cast<const std::uint16_t*>(in);
  const auto put = [](unsigned char* o, std::uint16_t v) {
    o[0] = static_cast<unsigned char>(v >> 8);
    o[1] = static_cast<unsigned char>(v);
  };
  if (channels == 1) {
    for (int x = 0; x < width; ++x) put(out + 2 * x, s[x]);
    return;
  }
  for (int x = 0; x < width; ++x, s += channels, out += 2 * channels) {
    put(out, s[2]);
    put(out + 2, s[1]);
    put(out + 4, s[0]);
    if (channels == 4) put(out + 6, s[3]);
  }
}

// libpng's measure of a filtered byte: its distance from zero, bytes >= 128 counting as negative.
inline unsigned cost(unsigned char v) { return std::min<unsigned char>(v, static_cast<unsigned char>(0u - v)); }

// The sum of cost() over bytes p[0..n-1]. With SSE2 16 bytes at a time: min(v, 0 - v) per byte, summed by
// psadbw into two 64-bit lanes (exact: the same sum as the scalar loop).
unsigned cost_sum(const unsigned char* p, std::size_t n) {
  std::size_t i = 0;
  unsigned sum = 0;
#ifdef __SSE2__
  const __m128i zero = _mm_setzero_si128();
  __m128i acc = zero;
  for (; i + 16 <= n; i += 16) {
    const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p + i));
    acc = _mm_add_epi64(acc, _mm_sad_epu8(_mm_min_epu8(v, _mm_sub_epi8(zero, v)), zero));
  }
  alignas(16) std::uint64_t lanes[2];
  _mm_store_si128(reinterpret_cast<__m128i*>(lanes), acc);
  sum = static_cast<unsigned>(lanes[0] + lanes[1]);
#endif
  for (; i < n; ++i) sum += cost(p[i]);
  return sum;
}

// The five filters of a row (PNG specification, section 9) with their costs: a is the byte bpp to the left,
// b the byte above, c the byte above-left (0 outside the row). Each loop is branch-free so that it vectorises.
struct FilteredRows {
  std::vector<unsigned char> rows[5];  // filter byte, then the filtered bytes
  unsigned sums[5] = {};
};

// The Paeth filter of bytes Bpp.. of a row (the first Bpp are done by the caller).
template <int Bpp>
void paeth_row(const unsigned char* raw, const unsigned char* prior, std::size_t n, unsigned char* paeth) {
  std::size_t i = Bpp;
#ifdef __SSE2__
  // Eight bytes at a time in 16-bit lanes: the same predictor as the scalar loop below.
  const __m128i zero = _mm_setzero_si128();
  const auto abs16 = [&](__m128i v) { return _mm_max_epi16(v, _mm_sub_epi16(zero, v)); };
  for (; i + 8 <= n; i += 8) {
    const auto load8 = [&](const unsigned char* p) {
      return _mm_unpacklo_epi8(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(p)), zero);
    };
    const __m128i a = load8(raw + i - Bpp), b = load8(prior + i), c = load8(prior + i - Bpp);
    const __m128i p = _mm_sub_epi16(b, c), q = _mm_sub_epi16(a, c);
    const __m128i pa = abs16(p), pb = abs16(q), pc = abs16(_mm_add_epi16(p, q));
    // take a where pa <= pb and pa <= pc; else b where pb <= pc; else c
    const __m128i take_a = _mm_andnot_si128(_mm_or_si128(_mm_cmpgt_epi16(pa, pb), _mm_cmpgt_epi16(pa, pc)),
                                            _mm_set1_epi16(-1));
    const __m128i take_b = _mm_andnot_si128(_mm_cmpgt_epi16(pb, pc), _mm_set1_epi16(-1));
    const __m128i b_or_c = _mm_or_si128(_mm_and_si128(take_b, b), _mm_andnot_si128(take_b, c));
    const __m128i predictor = _mm_or_si128(_mm_and_si128(take_a, a), _mm_andnot_si128(take_a, b_or_c));
    const __m128i x = load8(raw + i);
    const __m128i filtered = _mm_packus_epi16(_mm_and_si128(_mm_sub_epi16(x, predictor), _mm_set1_epi16(0xff)), zero);
    _mm_storel_epi64(reinterpret_cast<__m128i*>(paeth + i), filtered);
  }
#endif
  for (; i < n; ++i) {
    const int a = raw[i - Bpp], b = prior[i], c = prior[i - Bpp];
    const int p = b - c, q = a - c;
    const int pa = std::abs(p), pb = std::abs(q), pc = std::abs(p + q);
    const int predictor = (pa <= pb && pa <= pc) ? a : (pb <= pc ? b : c);
    paeth[i] = static_cast<unsigned char>(raw[i] - predictor);
  }
}

template <int Bpp>
void filter_all(const unsigned char* raw, const unsigned char* prior, std::size_t n, FilteredRows& f) {
  unsigned char* sub = f.rows[1].data() + 1;
  unsigned char* up = f.rows[2].data() + 1;
  unsigned char* avg = f.rows[3].data() + 1;
  unsigned char* paeth = f.rows[4].data() + 1;
  for (std::size_t i = 0; i < Bpp; ++i) {
    sub[i] = raw[i];
    avg[i] = static_cast<unsigned char>(raw[i] - (prior[i] >> 1));
    paeth[i] = static_cast<unsigned char>(raw[i] - prior[i]);
  }
  for (std::size_t i = Bpp; i < n; ++i) sub[i] = static_cast<unsigned char>(raw[i] - raw[i - Bpp]);
  for (std::size_t i = 0; i < n; ++i) up[i] = static_cast<unsigned char>(raw[i] - prior[i]);
  for (std::size_t i = Bpp; i < n; ++i) {
    avg[i] = static_cast<unsigned char>(raw[i] - ((unsigned{raw[i - Bpp]} + prior[i]) >> 1));
  }
  paeth_row<Bpp>(raw, prior, n, paeth);
  f.sums[0] = cost_sum(raw, n);
  f.sums[1] = cost_sum(sub, n);
  f.sums[2] = cost_sum(up, n);
  f.sums[3] = cost_sum(avg, n);
  f.sums[4] = cost_sum(paeth, n);
}

void filter_all(int bpp, const unsigned char* raw, const unsigned char* prior, std::size_t n, FilteredRows& f) {
  switch (bpp) {
    case 1: filter_all<1>(raw, prior, n, f); break;
    case 2: filter_all<2>(raw, prior, n, f); break;
    case 3: filter_all<3>(raw, prior, n, f); break;
    case 4: filter_all<4>(raw, prior, n, f); break;
    case 6: filter_all<6>(raw, prior, n, f); break;
    default: filter_all<8>(raw, prior, n, f); break;
  }
}

// The signature and IHDR of an image the direct paths take.
std::vector<unsigned char> start_png(const cv::Mat& image, std::size_t reserve) {
  const int channels = image.channels();
  const int sample_bytes = image.depth() == CV_8U ? 1 : 2;
  std::vector<unsigned char> out;
  out.reserve(reserve);
  const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  out.insert(out.end(), signature, signature + 8);
  unsigned char header[13];
  store32(header, static_cast<std::uint32_t>(image.cols));
  store32(header + 4, static_cast<std::uint32_t>(image.rows));
  header[8] = static_cast<unsigned char>(8 * sample_bytes);
  header[9] = static_cast<unsigned char>(channels == 1 ? 0 : (channels == 3 ? 2 : 6));
  header[10] = header[11] = header[12] = 0;  // deflate, filter method 0, no interlace
  put_chunk(out, "IHDR", header, sizeof header);
  return out;
}

// Filters the image's rows in PNG order with libpng's adaptive choice and hands each to `row(bytes, n + 1)`:
// the filter byte, then the n filtered bytes (valid until the next call).
template <typename RowSink>
void for_each_filtered_row(const cv::Mat& image, RowSink&& row) {
  const int channels = image.channels();
  const int sample_bytes = image.depth() == CV_8U ? 1 : 2;
  const int bpp = channels * sample_bytes;
  const std::size_t n = static_cast<std::size_t>(image.cols) * static_cast<std::size_t>(bpp);
  thread_local FilteredRows f;
  thread_local std::vector<unsigned char> raw, prior;
  for (int k = 0; k < 5; ++k) {
    f.rows[k].resize(n + 1);
    f.rows[k][0] = static_cast<unsigned char>(k);
  }
  raw.resize(n);
  prior.assign(n, 0);
  for (int y = 0; y < image.rows; ++y) {
    to_png_order(image.ptr(y), raw.data(), image.cols, channels, sample_bytes);
    filter_all(bpp, raw.data(), prior.data(), n, f);
    int best = 0;
    for (int k = 1; k < 5; ++k) {
      if (f.sums[k] < f.sums[best]) best = k;
    }
    if (best == 0) std::memcpy(f.rows[0].data() + 1, raw.data(), n);
    row(f.rows[best].data(), n + 1);
    std::swap(raw, prior);
  }
}

std::size_t row_bytes_of(const cv::Mat& image) {
  return static_cast<std::size_t>(image.cols) * static_cast<std::size_t>(image.channels()) *
         (image.depth() == CV_8U ? 1 : 2);
}

struct Deflater {
  z_stream z{};
  bool open = false;
  ~Deflater() {
    if (open) deflateEnd(&z);
  }
};

// cv::imencode's bytes: zlib fed row by row, IDAT chunks of kIdatBytes.
std::vector<unsigned char> encode_zlib(const cv::Mat& image, int level) {
  const std::size_t n = row_bytes_of(image);
  std::vector<unsigned char> out = start_png(image, 64 + n * static_cast<std::size_t>(image.rows) / 2);

  // A fresh stream per image, as libpng makes one: a reset stream may see another image's bytes past the
  // end of its data in zlib's window, which can change the last match chosen.
  Deflater d;
  if (deflateInit2(&d.z, level, Z_DEFLATED, 15, 8, Z_DEFAULT_STRATEGY) != Z_OK) {
    throw Error("PNG encoding: zlib could not start a stream");
  }
  d.open = true;
  std::array<unsigned char, kIdatBytes> idat{};
  d.z.next_out = idat.data();
  d.z.avail_out = kIdatBytes;
  const auto drain = [&](int flush) {
    while (true) {
      const int ret = deflate(&d.z, flush);
      if (ret != Z_OK && ret != Z_STREAM_END && ret != Z_BUF_ERROR) throw Error("PNG encoding: zlib failed");
      if (d.z.avail_out == 0) {
        put_chunk(out, "IDAT", idat.data(), kIdatBytes);
        d.z.next_out = idat.data();
        d.z.avail_out = kIdatBytes;
        continue;
      }
      if (ret == Z_STREAM_END) {
        const std::size_t used = kIdatBytes - d.z.avail_out;
        if (used > 0) put_chunk(out, "IDAT", idat.data(), used);
        return;
      }
      if (flush == Z_NO_FLUSH && d.z.avail_in == 0) return;
    }
  };
  for_each_filtered_row(image, [&](unsigned char* bytes, std::size_t size) {
    d.z.next_in = bytes;
    d.z.avail_in = static_cast<uInt>(size);
    drain(Z_NO_FLUSH);
  });
  drain(Z_FINISH);
  put_chunk(out, "IEND", nullptr, 0);
  return out;
}

struct CompressorDeleter {
  void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
};

// This thread's libdeflate compressor of `level` (0..12), made on first use.
libdeflate_compressor* thread_compressor(int level) {
  thread_local std::array<std::unique_ptr<libdeflate_compressor, CompressorDeleter>, 13> compressors;
  auto& c = compressors[static_cast<std::size_t>(level)];
  if (!c) c.reset(libdeflate_alloc_compressor(level));
  if (!c) throw Error("PNG encoding: libdeflate could not make a compressor of level " + std::to_string(level));
  return c.get();
}

// The filtered rows gathered, compressed in one call into one IDAT chunk written in place.
std::vector<unsigned char> encode_libdeflate(const cv::Mat& image, int level) {
  const std::size_t n = row_bytes_of(image);
  const std::size_t data_size = static_cast<std::size_t>(image.rows) * (n + 1);
  thread_local std::vector<unsigned char> filtered;
  filtered.resize(data_size);
  std::size_t at = 0;
  for_each_filtered_row(image, [&](const unsigned char* bytes, std::size_t size) {
    std::memcpy(filtered.data() + at, bytes, size);
    at += size;
  });
  libdeflate_compressor* compressor = thread_compressor(level);
  const std::size_t bound = libdeflate_zlib_compress_bound(compressor, data_size);
  std::vector<unsigned char> out = start_png(image, 33 + 12 + bound + 12);
  const std::size_t chunk_at = out.size();
  out.resize(chunk_at + 8 + bound);
  std::memcpy(out.data() + chunk_at + 4, "IDAT", 4);
  const std::size_t size =
      libdeflate_zlib_compress(compressor, filtered.data(), data_size, out.data() + chunk_at + 8, bound);
  if (size == 0) throw Error("PNG encoding: libdeflate failed");
  out.resize(chunk_at + 8 + size);
  store32(out.data() + chunk_at, static_cast<std::uint32_t>(size));
  put32(out, static_cast<std::uint32_t>(libdeflate_crc32(0, out.data() + chunk_at + 4, size + 4)));
  put_chunk(out, "IEND", nullptr, 0);
  return out;
}

}  // namespace

std::vector<unsigned char> encode_png(const cv::Mat& image, const PngEncodeOptions& options) {
  const bool libdeflate = options.deflater == PngDeflater::libdeflate;
  if (libdeflate && (options.libdeflate_level < 0 || options.libdeflate_level > 12)) {
    throw Error("PNG encoding: libdeflate level " + std::to_string(options.libdeflate_level) + " is not in 0..12");
  }
  const int channels = image.channels();
  const bool plain = (image.depth() == CV_8U || image.depth() == CV_16U) &&
                     (channels == 1 || channels == 3 || channels == 4) && image.dims == 2;
  if (options.direct_path && plain && !image.empty() && row_bytes_of(image) < (1u << 24)) {
    const std::size_t data_size = static_cast<std::size_t>(image.rows) * (row_bytes_of(image) + 1);
    // libdeflate: any size (no zlib window to match); zlib: libpng's window below kSmallWindowFrom is not.
    if (libdeflate) return encode_libdeflate(image, options.libdeflate_level);
    if (data_size > kSmallWindowFrom && options.zlib_level >= 0 && options.zlib_level <= 9) {
      return encode_zlib(image, options.zlib_level);
    }
  }
  std::vector<unsigned char> bytes;
  bool ok = false;
  try {
    ok = !image.empty() && opencv_encode_png(image, bytes, options.zlib_level);
  } catch (const cv::Exception&) {
    ok = false;
  }
  if (!ok) throw Error("PNG encoding failed");
  return bytes;
}

}  // namespace rdsf
