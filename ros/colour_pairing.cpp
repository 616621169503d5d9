#include "ros/colour_pairing.hpp"

#include <cstdlib>
#include <utility>

namespace rdsf {

ColourPairing::ColourPairing(std::int64_t max_gap_us, std::int64_t stale_after_us, std::size_t history,
                             ColourWait wait)
    : max_gap_us_(max_gap_us), stale_after_us_(stale_after_us), history_(history), wait_(wait) {}

std::vector<PairedFrame> ColourPairing::add_depth(DepthFrame frame) {
  std::vector<PairedFrame> out = flush();
  const std::int64_t t = frame.timestamp_us;
  std::size_t best = colours_.size();
  for (std::size_t i = 0; i < colours_.size(); ++i) {
    if (best == colours_.size() || std::llabs(colours_[i].stamp_us - t) < std::llabs(colours_[best].stamp_us - t)) best = i;
  }
  if (best < colours_.size() && std::llabs(colours_[best].stamp_us - t) <= max_gap_us_) {
    frame.bgr = colours_[best].bgr;
    const std::int64_t gap = std::llabs(colours_[best].stamp_us - t);
    // Older images go; without waiting the one taken stays for the next frame too, should its own colour
    // image come after it.
    const std::size_t kept = wait_ == ColourWait::never ? 0 : 1;
    colours_.erase(colours_.begin(), colours_.begin() + static_cast<std::ptrdiff_t>(best + kept));
    out.push_back({std::move(frame), gap});
    return out;
  }
  if (wait_ == ColourWait::never) {
    out.push_back({std::move(frame), -1});
    return out;
  }
  const bool passed = newest_colour_us_ && *newest_colour_us_ > t + max_gap_us_;
  if (!first_depth_us_) first_depth_us_ = t;
  const bool stale = newest_colour_us_ ? *newest_colour_us_ < t - stale_after_us_ : t - *first_depth_us_ > stale_after_us_;
  if (passed || stale) {
    out.push_back({std::move(frame), -1});
  } else {
    waiting_ = std::move(frame);
  }
  return out;
}

std::vector<PairedFrame> ColourPairing::add_colour(std::int64_t stamp_us, cv::Mat3b bgr) {
  newest_colour_us_ = stamp_us;  // the last to arrive (stamps may start again: a bag played in a loop)
  std::vector<PairedFrame> out;
  if (waiting_ && std::llabs(waiting_->timestamp_us - stamp_us) <= max_gap_us_) {
    const std::int64_t gap = std::llabs(waiting_->timestamp_us - stamp_us);
    waiting_->bgr = std::move(bgr);
    out.push_back({std::move(*waiting_), gap});
    waiting_.reset();
    return out;
  }
  colours_.push_back({stamp_us, std::move(bgr)});
  while (colours_.size() > history_) colours_.pop_front();
  if (waiting_ && stamp_us > waiting_->timestamp_us + max_gap_us_) out = flush();
  return out;
}

std::vector<PairedFrame> ColourPairing::flush() {
  std::vector<PairedFrame> out;
  if (waiting_) {
    out.push_back({std::move(*waiting_), -1});
    waiting_.reset();
  }
  return out;
}

}  // namespace rdsf
