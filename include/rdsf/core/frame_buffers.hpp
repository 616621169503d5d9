#pragma once
// Images a frame's analysis makes anew for every frame (the segmentation's labels, in_front_of()'s, the
// local background), taken from a small pool of this thread's instead of from the allocator. A buffer is
// handed out again once every cv::Mat that shared it has been released (OpenCV's reference count back to
// the pool's own 1), so a detector that drops each frame's analysis before the next touches no fresh page;
// an analysis still held (a pipeline's frames in flight, a labeller's history) keeps its buffer, and the
// pool hands out another or a new one. Why: glibc maps an allocation above its mmap threshold afresh, and
// that threshold moves with what the program freed before, so the same detector ran a frame in 0.9 ms or
// 2.4 ms by its host program's allocation history: each fresh page a fault, about 150 a 640x480 frame
// (docs/performance.md, "Fresh pages per frame").
// Contents are whatever the last user left: a caller writes every pixel.
#include <opencv2/core.hpp>

namespace rdsf {

enum class FrameBuffer { segmentation_labels, in_front_labels, local_far, last = local_far };

/// Buffers kept per use and thread; beyond them a busy pool hands out unpooled images.
constexpr int kFrameBuffersPerUse = 4;

/// A `size` image of `type` for `use`: one of this thread's buffers that nobody else holds, else a new one.
cv::Mat frame_buffer(FrameBuffer use, cv::Size size, int type);

}  // namespace rdsf
