#include "rdsf/frame/png_decoder.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <type_traits>
#include <vector>

#include <libdeflate.h>
#ifdef __SSE2__
#include <emmintrin.h>
#endif

#include "rdsf/core/byte_order.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/core/yaml_guard.hpp"
#include "rdsf/frame/image_codecs.hpp"

namespace rdsf {
namespace {

const unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

bool chunk_is(const unsigned char* type, const char* name) { return std::memcmp(type, name, 4) == 0; }

// What the chunk walk learns for the direct path.
struct PngLayout {
  std::uint32_t width = 0, height = 0;
  int bit_depth = 0, colour_type = -1;
  bool direct = true;  // false as soon as something outside the direct path's subset is seen
  std::vector<std::pair<std::size_t, std::size_t>> idat;  // offset and length of each IDAT's data
};

// Walks the PNG chunks and checks every CRC (the same messages as before the direct path existed), and
// records the header and the IDAT chunks.
PngLayout walk_chunks(const std::string& path, const unsigned char* bytes, std::size_t size) {
  if (size < 8 || !std::equal(kPngSignature, kPngSignature + 8, bytes)) fail(path, "not a PNG file");
  PngLayout layout;
  std::size_t at = 8;
  bool idat_closed = false;
  for (int index = 0;; ++index) {
    if (at + 12 > size) {
      fail(path, "truncated PNG (file ends at byte " + std::to_string(size) + " before the IEND chunk)");
    }
    const std::size_t length = load_big_endian_u32(&bytes[at]);
    if (length > size - at - 12) {
      fail(path, "truncated PNG (chunk at byte " + std::to_string(at) + " runs past the end of the file)");
    }
    const unsigned char* type = &bytes[at + 4];
    const std::uint32_t crc = static_cast<std::uint32_t>(libdeflate_crc32(0, type, length + 4));
    if (crc != load_big_endian_u32(&bytes[at + 8 + length])) {
      fail(path, "corrupt PNG (CRC error in " + one_line(std::string(reinterpret_cast<const char*>(type), 4)) +
                     " chunk at byte " + std::to_string(at) + ")");
    }
    const unsigned char* data = &bytes[at + 8];
    if (index == 0) {
      if (!chunk_is(type, "IHDR") || length != 13) {
        layout.direct = false;
      } else {
        layout.width = load_big_endian_u32(data);
        layout.height = load_big_endian_u32(data + 4);
        layout.bit_depth = data[8];
        layout.colour_type = data[9];
        const bool plain = data[10] == 0 && data[11] == 0 && data[12] == 0;  // deflate, filter 0, no interlace
        layout.direct = plain && (layout.bit_depth == 8 || layout.bit_depth == 16) &&
                        (layout.colour_type == 0 || layout.colour_type == 2 || layout.colour_type == 6) &&
                        layout.width >= 1 && layout.width <= 65535 && layout.height >= 1 &&
                        layout.height <= 65535 && std::uint64_t{layout.width} * layout.height <= (1U << 26);
      }
    } else if (chunk_is(type, "IDAT")) {
      if (idat_closed) layout.direct = false;
      layout.idat.emplace_back(at + 8, length);
    } else {
      if (!layout.idat.empty()) idat_closed = true;
      // Chunks libpng reads without changing the pixels it returns unless asked (cv::imdecode never asks
      // for gamma, background or colour-space transforms).
      bool harmless = false;
      for (const char* name : {"IEND", "tEXt", "zTXt", "iTXt", "tIME", "pHYs", "gAMA", "cHRM", "sRGB", "bKGD", "sBIT"}) {
        harmless = harmless || chunk_is(type, name);
      }
      if (!harmless) layout.direct = false;
    }
    at += length + 12;
    if (chunk_is(type, "IEND")) return layout;
  }
}

struct DecompressorDeleter {
  void operator()(libdeflate_decompressor* d) const { libdeflate_free_decompressor(d); }
};

libdeflate_decompressor* thread_decompressor() {
  thread_local std::unique_ptr<libdeflate_decompressor, DecompressorDeleter> d(libdeflate_alloc_decompressor());
  return d.get();
}

// Undoes one row's filter in place. `prior` is the unfiltered row above (zeros for the first row).
// Filters (PNG specification, section 9): 1 Sub x += a, 2 Up x += b, 3 Average x += (a + b) / 2,
// 4 Paeth x += the one of a, b, c nearest to a + b - c (ties a, then b), where a is the byte bpp to the
// left, b the byte above, c the byte above-left (0 outside the row).
// Sub: x += a, a running sum per byte position of a pixel. With SSE2 a block of whole pixels (16 bytes, 15
// for 3 bytes a pixel) at a time: the previous block's last pixel added to the first, then a prefix sum of
// the block by shifts of 1, 2, 4, 8 pixels; bytes past the block keep their value.
template <int Bpp>
void unsub_row(unsigned char* row, std::size_t n) {
  std::size_t i = Bpp;
#ifdef __SSE2__
  constexpr int kPixels = 16 / Bpp, kBlock = kPixels * Bpp;
  if (n >= 2 * kBlock) {
    __m128i carry = _mm_setzero_si128();  // the last pixel of the previous block, in bytes 0..Bpp-1
    const __m128i first_pixel = _mm_srli_si128(_mm_set1_epi8(-1), 16 - Bpp);
    const __m128i block = _mm_srli_si128(_mm_set1_epi8(-1), 16 - kBlock);
    std::size_t at = 0;
    __m128i next = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row));
    for (; at + 16 <= n; at += kBlock) {
      const __m128i x = next;
      // the next block's bytes, loaded before this block is stored (they do not overlap what it changes):
      // a load of bytes just stored would wait for the store
      if (at + kBlock + 16 <= n) next = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row + at + kBlock));
      __m128i v = _mm_add_epi8(x, carry);
      v = _mm_add_epi8(v, _mm_slli_si128(v, Bpp));
      if (kPixels > 2) v = _mm_add_epi8(v, _mm_slli_si128(v, 2 * Bpp));
      if (kPixels > 4) v = _mm_add_epi8(v, _mm_slli_si128(v, (4 * Bpp) & 15));
      if (kPixels > 8) v = _mm_add_epi8(v, _mm_slli_si128(v, (8 * Bpp) & 15));
      v = _mm_or_si128(_mm_and_si128(block, v), _mm_andnot_si128(block, x));  // the 16th byte of 15 kept
      _mm_storeu_si128(reinterpret_cast<__m128i*>(row + at), v);
      carry = _mm_and_si128(_mm_srli_si128(v, kBlock - Bpp), first_pixel);
    }
    i = std::max<std::size_t>(at, Bpp);
  }
#endif
  for (; i < n; ++i) row[i] = static_cast<unsigned char>(row[i] + row[i - Bpp]);
}

// Paeth: x += the one of a, b, c nearest to p = a + b - c, ties a, then b. With pa = |p - a| = |b - c|,
// pb = |p - b| = |a - c|, pc = |p - c| = |(a - c) + (b - c)|: a when pa <= pb and pa <= pc, else b when
// pb <= pc, else c. Each pixel needs the one just reconstructed on its left (a), so a row is a chain of
// pixels; with SSE2 a pixel's bytes go through it together, in 16-bit lanes, without branches (the scalar
// choice mispredicts on noisy rows: real colour frames are nearly all Paeth rows, and decoding them took 5
// of their 7 ms). The chain's latency, not the work, bounds a row; runs of 2 to 4 Paeth rows (most of the
// real frames' Paeth rows) are done together, each row two pixels behind the one above it, in one
// register of 8-bit lanes (unpaeth_rows below). Bytes outside a pixel are not written; up to 8 bytes
// past it are read.
constexpr std::size_t kRowSlack = 32;  // readable bytes after the last row and after `prior`

inline int paeth_predictor(int a, int b, int c) {
  const int pa = std::abs(b - c), pb = std::abs(a - c), pc = std::abs(a + b - 2 * c);
  return (pa <= pb && pa <= pc) ? a : (pb <= pc ? b : c);
}

// Bytes from..n of a Paeth row, one at a time (from >= Bpp).
template <int Bpp>
void unpaeth_bytes(unsigned char* row, const unsigned char* prior, std::size_t from, std::size_t n) {
  for (std::size_t i = from; i < n; ++i) {
    row[i] = static_cast<unsigned char>(row[i] + paeth_predictor(row[i - Bpp], prior[i], prior[i - Bpp]));
  }
}

#ifdef __SSE2__
// x + the Paeth predictor in each 16-bit lane (samples 0..255): the next a.
inline __m128i paeth_lanes(__m128i a, __m128i b, __m128i c, __m128i x) {
  const __m128i zero = _mm_setzero_si128(), low_byte = _mm_set1_epi16(0x00ff);
  const auto abs16 = [](__m128i v, __m128i negated) { return _mm_max_epi16(v, negated); };
  const __m128i bc = _mm_sub_epi16(b, c);  // b - c: off the chain of a single row
  const __m128i pa = abs16(bc, _mm_sub_epi16(zero, bc));
  const __m128i xb = _mm_and_si128(_mm_add_epi16(x, b), low_byte), xc = _mm_and_si128(_mm_add_epi16(x, c), low_byte);
  const __m128i ac = _mm_sub_epi16(a, c), ca = _mm_sub_epi16(c, a);
  const __m128i pb = abs16(ac, ca);
  const __m128i pc = abs16(_mm_add_epi16(ac, bc), _mm_sub_epi16(ca, bc));
  const __m128i xa = _mm_and_si128(_mm_add_epi16(x, a), low_byte);
  const __m128i not_a = _mm_or_si128(_mm_cmpgt_epi16(pa, pb), _mm_cmpgt_epi16(pa, pc));
  const __m128i take_c = _mm_cmpgt_epi16(pb, pc);
  const __m128i b_or_c = _mm_or_si128(_mm_and_si128(take_c, xc), _mm_andnot_si128(take_c, xb));
  return _mm_or_si128(_mm_and_si128(not_a, b_or_c), _mm_andnot_si128(not_a, xa));
}

// The 8 bytes at p in 16-bit lanes.
inline __m128i load_lanes(const unsigned char* p) {
  return _mm_unpacklo_epi8(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(p)), _mm_setzero_si128());
}

// The 4 bytes at p, zero-extended to a 32-bit value's register.
inline __m128i load4(const unsigned char* p) {
  std::uint32_t v;
  std::memcpy(&v, p, 4);
  return _mm_cvtsi32_si128(static_cast<int>(v));
}

// Writes the low Bpp bytes of `bytes` (Bpp <= 8) to out, from registers where it can.
template <int Bpp>
inline void store_pixel(unsigned char* out, std::uint64_t bytes) {
  if (Bpp == 1 || Bpp == 3) out[Bpp - 1] = static_cast<unsigned char>(bytes >> (8 * (Bpp - 1)));
  if (Bpp == 2 || Bpp == 3) {
    const auto low = static_cast<std::uint16_t>(bytes);
    std::memcpy(out, &low, 2);
  }
  if (Bpp == 4) {
    const auto low = static_cast<std::uint32_t>(bytes);
    std::memcpy(out, &low, 4);
  }
  if (Bpp > 4) std::memcpy(out, &bytes, Bpp);
}

inline std::uint64_t low_bytes(__m128i lanes) {
  std::uint64_t out;
  _mm_storel_epi64(reinterpret_cast<__m128i*>(&out), _mm_packus_epi16(lanes, _mm_setzero_si128()));
  return out;
}
#endif

template <int Bpp>
void unpaeth_row(unsigned char* row, const unsigned char* prior, std::size_t n) {
  for (std::size_t i = 0; i < Bpp && i < n; ++i) row[i] = static_cast<unsigned char>(row[i] + prior[i]);
  std::size_t i = Bpp;
#ifdef __SSE2__
  if (n >= 2 * Bpp) {
    __m128i a = load_lanes(row), c = load_lanes(prior);
    for (; i + Bpp <= n; i += Bpp) {
      const __m128i b = load_lanes(prior + i);
      a = paeth_lanes(a, b, c, load_lanes(row + i));
      c = b;
      store_pixel<Bpp>(row + i, low_bytes(a));
    }
  }
#endif
  unpaeth_bytes<Bpp>(row, prior, i, n);
}

#ifdef __SSE2__
// The kernels below are called once per pixel: GCC must not leave them as calls.
#if defined(__GNUC__)
#define RDSF_PNG_INLINE inline __attribute__((always_inline))
#define RDSF_PNG_INLINE_LAMBDA __attribute__((always_inline))
#else
#define RDSF_PNG_INLINE inline
#define RDSF_PNG_INLINE_LAMBDA
#endif
// Paeth in 8-bit lanes: x + the predictor of a, b, c in each byte, given pa = |b - c| and the masks
// b_ge_c (b >= c). With pb = |a - c|: when a - c and b - c have the same sign, pc = pa + pb >= pa, pb,
// so the predictor is a when pa <= pb, else b. When they differ, pc = |pa - pb|: a when pa <= pb - pa,
// else b when pb <= pa - pb, else c (pa <= pb and pb <= pb - pa would mean pa = 0: a). Every
// difference here is taken only where it is not negative, so bytes and saturating subtraction hold it
// exactly. Unsigned u <= v is (u - v saturated) == 0.
RDSF_PNG_INLINE __m128i paeth_bytes(__m128i a, __m128i b, __m128i c, __m128i x, __m128i pa, __m128i b_ge_c) {
  const __m128i zero = _mm_setzero_si128();
  const __m128i ac = _mm_subs_epu8(a, c), ca = _mm_subs_epu8(c, a);
  const __m128i pb = _mm_or_si128(ac, ca);
  const __m128i same_sign = _mm_cmpeq_epi8(_mm_cmpeq_epi8(ca, zero), b_ge_c);
  const __m128i pa_over = _mm_subs_epu8(pa, pb), pb_over = _mm_subs_epu8(pb, pa);
  const __m128i a_same = _mm_cmpeq_epi8(pa_over, zero);
  const __m128i a_differ = _mm_cmpeq_epi8(_mm_subs_epu8(pa, pb_over), zero);
  const __m128i b_differ = _mm_cmpeq_epi8(_mm_subs_epu8(pb, pa_over), zero);
  const __m128i take_a = _mm_or_si128(_mm_and_si128(same_sign, a_same), _mm_andnot_si128(same_sign, a_differ));
  const __m128i take_b = _mm_or_si128(same_sign, b_differ);
  const __m128i b_or_c = _mm_or_si128(_mm_and_si128(take_b, b), _mm_andnot_si128(take_b, c));
  return _mm_add_epi8(x, _mm_or_si128(_mm_and_si128(take_a, a), _mm_andnot_si128(take_a, b_or_c)));
}

// Rows consecutive Paeth rows (Rows <= 4, Bpp <= 4), the first at `first` with `prior` above it, each
// `stride` bytes after the one before, done as a wavefront: at step p, row k takes its pixel q = p - 2k, in
// bytes 4k..4k+3 of one register (bytes past Bpp are not stored). Its a is its own previous result; its b
// (pixel q of the row above) is that row's result two steps before, its c (pixel q - 1 above) the b of
// the step before: only a is carried from one step to the next (the chain that bounds Paeth), b and c
// are ready a step early. The first row's b and c come from `prior`. Before a row starts its bytes are 0,
// which Paeth of 0, 0, 0 and x = 0 keeps: pixel 0 sees a = c = 0, as outside the row; after a row ends
// nothing of it is stored. Up to 24 bytes past a row (n) and past `prior` are read.
template <int Bpp, int Rows>
void unpaeth_rows(unsigned char* first, std::size_t stride, const unsigned char* prior, std::size_t n) {
  static_assert(Bpp <= 4 && Rows <= 4, "a pixel of each row in one register");
  const std::size_t pixels = n / Bpp;
  __m128i a = _mm_setzero_si128(), result_1 = a, result_2 = a, b_1 = a;
  unsigned char* row[4];
  for (int k = 0; k < 4; ++k) row[k] = first + k * stride;
  const auto step = [&](std::size_t p, bool edge) RDSF_PNG_INLINE_LAMBDA {
    // x: row k's bytes at pixel q = p - 2k (0 before the row starts)
    std::uint32_t x[4] = {0, 0, 0, 0};
    for (int k = 0; k < Rows; ++k) {
      if (!edge || p >= static_cast<std::size_t>(2 * k)) std::memcpy(&x[k], row[k] + (p - 2 * k) * Bpp, 4);
    }
    const __m128i xs = _mm_unpacklo_epi64(_mm_unpacklo_epi32(_mm_cvtsi32_si128(static_cast<int>(x[0])),
                                                             _mm_cvtsi32_si128(static_cast<int>(x[1]))),
                                          _mm_unpacklo_epi32(_mm_cvtsi32_si128(static_cast<int>(x[2])),
                                                             _mm_cvtsi32_si128(static_cast<int>(x[3]))));
    const __m128i b = _mm_or_si128(_mm_slli_si128(result_2, 4), load4(prior + p * Bpp));
    const __m128i c = b_1;
    const __m128i pa = _mm_or_si128(_mm_subs_epu8(b, c), _mm_subs_epu8(c, b));
    const __m128i b_ge_c = _mm_cmpeq_epi8(_mm_subs_epu8(c, b), _mm_setzero_si128());
    a = paeth_bytes(a, b, c, xs, pa, b_ge_c);
    result_2 = result_1;
    result_1 = a;
    b_1 = b;
    std::uint64_t low, high;
    _mm_storel_epi64(reinterpret_cast<__m128i*>(&low), a);
    _mm_storel_epi64(reinterpret_cast<__m128i*>(&high), _mm_unpackhi_epi64(a, a));
    for (int k = 0; k < Rows; ++k) {
      const std::size_t q = p - 2 * k;
      if (!edge || (p >= static_cast<std::size_t>(2 * k) && q < pixels)) {
        store_pixel<Bpp>(row[k] + q * Bpp, (k < 2 ? low : high) >> (32 * (k % 2)));
      }
    }
  };
  std::size_t p = 0;
  for (; p < 2 * (Rows - 1); ++p) step(p, true);
  for (; p < pixels; ++p) step(p, false);
  for (; p < pixels + 2 * (Rows - 1); ++p) step(p, true);
}
#endif

template <int Bpp>
void unfilter_row(int filter, unsigned char* row, const unsigned char* prior, std::size_t n) {
  switch (filter) {
    case 0: break;
    case 1: unsub_row<Bpp>(row, n); break;
    case 2:
      for (std::size_t i = 0; i < n; ++i) row[i] = static_cast<unsigned char>(row[i] + prior[i]);
      break;
    case 3:
      for (std::size_t i = 0; i < Bpp; ++i) row[i] = static_cast<unsigned char>(row[i] + (prior[i] >> 1));
      for (std::size_t i = Bpp; i < n; ++i) {
        row[i] = static_cast<unsigned char>(row[i] + ((unsigned{row[i - Bpp]} + prior[i]) >> 1));
      }
      break;
    case 4: unpaeth_row<Bpp>(row, prior, n); break;
  }
}

void unfilter(int bpp, int filter, unsigned char* row, const unsigned char* prior, std::size_t n) {
  switch (bpp) {
    case 1: unfilter_row<1>(filter, row, prior, n); break;
    case 2: unfilter_row<2>(filter, row, prior, n); break;
    case 3: unfilter_row<3>(filter, row, prior, n); break;
    case 4: unfilter_row<4>(filter, row, prior, n); break;
    case 6: unfilter_row<6>(filter, row, prior, n); break;
    default: unfilter_row<8>(filter, row, prior, n); break;
  }
}

// `rows` (2..4) consecutive Paeth rows, the first at `first`, each `stride` bytes after the one before;
// bpp <= 4.
void unpaeth_group(int bpp, int rows, unsigned char* first, std::size_t stride, const unsigned char* prior,
                   std::size_t n) {
#ifdef __SSE2__
  const auto with = [&](auto bpp_constant) {
    constexpr int kBpp = decltype(bpp_constant)::value;
    switch (rows) {
      case 2: unpaeth_rows<kBpp, 2>(first, stride, prior, n); break;
      case 3: unpaeth_rows<kBpp, 3>(first, stride, prior, n); break;
      default: unpaeth_rows<kBpp, 4>(first, stride, prior, n); break;
    }
  };
  switch (bpp) {
    case 1: with(std::integral_constant<int, 1>{}); break;
    case 2: with(std::integral_constant<int, 2>{}); break;
    case 3: with(std::integral_constant<int, 3>{}); break;
    default: with(std::integral_constant<int, 4>{}); break;
  }
#else
  for (int k = 0; k < rows; ++k, prior = first, first += stride) unfilter(bpp, 4, first, prior, n);
#endif
}

// One unfiltered PNG row to the cv::imdecode layout: 16-bit samples to host order, RGB(A) to BGR(A).
void convert_row(const unsigned char* in, unsigned char* out, std::size_t pixels, int channels, int bit_depth) {
  if (bit_depth == 8) {
    if (channels == 1) {
      std::memcpy(out, in, pixels);
      return;
    }
    std::size_t p = 0;
#ifdef __SSE2__
    if (channels == 3) {  // five pixels at a time: R and B swapped by shifts of two bytes
      const __m128i keep = _mm_setr_epi8(0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0);
      const __m128i from_right = _mm_setr_epi8(-1, 0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0, 0);
      const __m128i from_left = _mm_setr_epi8(0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1, 0, 0, -1, 0);
      // the 16th byte stored belongs to the next pixel, which the next block or the tail writes after
      for (; 3 * p + 16 <= 3 * pixels; p += 5, in += 15, out += 15) {
        const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(in));
        const __m128i bgr = _mm_or_si128(_mm_and_si128(v, keep),
                                         _mm_or_si128(_mm_and_si128(_mm_srli_si128(v, 2), from_right),
                                                      _mm_and_si128(_mm_slli_si128(v, 2), from_left)));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(out), bgr);
      }
    }
#endif
    for (; p < pixels; ++p, in += channels, out += channels) {
      out[0] = in[2];
      out[1] = in[1];
      out[2] = in[0];
      if (channels == 4) out[3] = in[3];
    }
    return;
  }
  auto* o = reinterpret_cast<std::uint16_t*>(out);
  const auto sample = [](const unsigned char* s) { return static_cast<std::uint16_t>((s[0] << 8) | s[1]); };
  if (channels == 1) {
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    for (std::size_t p = 0; p < pixels; ++p) {  // a byte swap of each sample, in a loop that vectorises
      std::uint16_t v;
      std::memcpy(&v, in + 2 * p, 2);
      o[p] = static_cast<std::uint16_t>((v >> 8) | (v << 8));
    }
#else
    for (std::size_t p = 0; p < pixels; ++p) o[p] = sample(in + 2 * p);
#endif
    return;
  }
  for (std::size_t p = 0; p < pixels; ++p, in += 2 * channels, o += channels) {
    o[0] = sample(in + 4);
    o[1] = sample(in + 2);
    o[2] = sample(in);
    if (channels == 4) o[3] = sample(in + 6);
  }
}

// The direct path; an empty result means "not decoded here" (cv::imdecode then decides).
cv::Mat decode_direct(const unsigned char* bytes, const PngLayout& layout) {
  const int channels = layout.colour_type == 0 ? 1 : (layout.colour_type == 2 ? 3 : 4);
  const int bpp = channels * layout.bit_depth / 8;
  const std::size_t row_bytes = std::size_t{layout.width} * bpp;
  const std::size_t raw_size = std::size_t{layout.height} * (row_bytes + 1);

  thread_local std::vector<unsigned char> joined, raw;
  const unsigned char* stream = nullptr;
  std::size_t stream_size = 0;
  if (layout.idat.size() == 1) {
    stream = bytes + layout.idat[0].first;
    stream_size = layout.idat[0].second;
  } else {
    std::size_t total = 0;
    for (const auto& chunk : layout.idat) total += chunk.second;
    joined.resize(total);
    std::size_t at = 0;
    for (const auto& chunk : layout.idat) {
      std::memcpy(joined.data() + at, bytes + chunk.first, chunk.second);
      at += chunk.second;
    }
    stream = joined.data();
    stream_size = total;
  }
  if (stream_size == 0) return {};
  raw.resize(raw_size + kRowSlack);
  std::size_t consumed = 0;
  const libdeflate_result result = libdeflate_zlib_decompress_ex(thread_decompressor(), stream, stream_size,
                                                                 raw.data(), raw_size, &consumed, nullptr);
  if (result != LIBDEFLATE_SUCCESS || consumed != stream_size) return {};

  const int type = layout.bit_depth == 8 ? CV_MAKETYPE(CV_8U, channels) : CV_MAKETYPE(CV_16U, channels);
  cv::Mat image(static_cast<int>(layout.height), static_cast<int>(layout.width), type);
  thread_local std::vector<unsigned char> zeros;
  zeros.assign(row_bytes + kRowSlack, 0);
  const unsigned char* prior = zeros.data();
  for (std::uint32_t y = 0; y < layout.height; ++y) {
    unsigned char* line = raw.data() + std::size_t{y} * (row_bytes + 1);
    const int filter = line[0];
    if (filter > 4) return {};
    // A run of 2 to 4 Paeth rows is undone together (their pixels side by side in one register).
    std::uint32_t run = 0;
    if (filter == 4 && bpp <= 4) {
      while (run < 4 && y + run < layout.height && line[std::size_t{run} * (row_bytes + 1)] == 4) ++run;
    }
    if (run >= 2) {
      unpaeth_group(bpp, static_cast<int>(run), line + 1, row_bytes + 1, prior, row_bytes);
      for (std::uint32_t k = 0; k + 1 < run; ++k, ++y, line += row_bytes + 1) {
        convert_row(line + 1, image.ptr(static_cast<int>(y)), layout.width, channels, layout.bit_depth);
      }
    } else {
      unfilter(bpp, filter, line + 1, prior, row_bytes);
    }
    convert_row(line + 1, image.ptr(static_cast<int>(y)), layout.width, channels, layout.bit_depth);
    prior = line + 1;
  }
  return image;
}

}  // namespace

cv::Mat decode_png(const std::string& path, const unsigned char* data, std::size_t size,
                   const PngDecodeOptions& options) {
  const PngLayout layout = walk_chunks(path, data, size);
  if (options.direct_path && layout.direct) {
    cv::Mat image = decode_direct(data, layout);
    if (!image.empty()) return image;
  }
  cv::Mat image;
  try {
    image = opencv_decode_image(data, size, DecodedAs::unchanged);
  } catch (const cv::Exception&) {
    image.release();
  }
  if (image.empty()) fail(path, "corrupt PNG (cannot be decoded)");
  return image;
}

std::vector<unsigned char> png_zlib_stream(const std::string& path, const unsigned char* data, std::size_t size) {
  std::vector<unsigned char> stream;
  for (const auto& chunk : walk_chunks(path, data, size).idat) {
    stream.insert(stream.end(), data + chunk.first, data + chunk.first + chunk.second);
  }
  return stream;
}

cv::Mat read_png_file(const std::string& path, const PngDecodeOptions& options) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    if (errno == ENOENT || errno == ENOTDIR) fail(path, "no such file");
    fail(path, "cannot be opened for reading");
  }
  struct FdCloser {
    int fd;
    ~FdCloser() { ::close(fd); }
  } closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) fail(path, "cannot be read");
  if (S_ISDIR(st.st_mode)) fail(path, "is a folder, expected a PNG file");
  thread_local std::vector<unsigned char> bytes;
  bytes.resize(static_cast<std::size_t>(std::max<off_t>(0, st.st_size)));
  std::size_t got = 0;
  while (got < bytes.size()) {
    const ssize_t n = ::read(fd, bytes.data() + got, bytes.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail(path, "cannot be read");
    got += static_cast<std::size_t>(n);
  }
  return decode_png(path, bytes.data(), bytes.size(), options);
}

}  // namespace rdsf
