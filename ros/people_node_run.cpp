#include "ros/people_node_run.hpp"

#include <iostream>
#include <map>
#include <mutex>

#include <cv_bridge/cv_bridge.h>
#include <image_transport/camera_common.h>
#include <image_transport/image_transport.h>
#include <message_filters/subscriber.h>
#include <message_filters/time_synchronizer.h>
#include <ros/ros.h>
#include <sensor_msgs/CompressedImage.h>

#include "rdsf/core/clock.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/core/thread_count.hpp"
#include "rdsf/frame/compressed_image.hpp"
#include "rdsf/frame/image_codecs.hpp"
#include "rdsf/pipeline/live_pipeline.hpp"
#include "rdsf/pipeline/people_detector.hpp"
#include "rdsf/pipeline/people_overlay.hpp"
#include "ros/colour_pairing.hpp"
#include "ros/image_frames.hpp"
#include "ros/node_diagnostics.hpp"
#include "ros/people_messages.hpp"

namespace rdsf {
namespace {

// The node's subscriptions, publishers and live pipeline. Callbacks run on ros::spin's thread; frames are
// analysed and published on the live pipeline's workers, one frame at a time in arrival order. A depth image
// meets its camera_info by exact stamp (CameraSubscriber) or, with ~camera_info latest, takes the newest
// camera_info received (its own subscription; before the first one the newest image waits for it). Depth
// and colour come raw (image_transport) or compressed (sensor_msgs/CompressedImage on the image topic's
// compressedDepth / compressed subtopic, decoded here); the frame's work is the same either way.
class PeopleNode {
 public:
  PeopleNode(ros::NodeHandle& nh, PeopleDetector& detector, const PeopleNodeOptions& o)
      : detector_(detector),
        pairing_(static_cast<std::int64_t>(o.colour_gap_ms * 1000.0), 1000000, 8,
                 o.colour_wait ? ColourWait::until_paired : ColourWait::never),
        transport_(nh),
        camera_info_(o.camera_info),
        people_(nh.advertise<rdsf_people::People>("people", 10)),
        markers_(nh.advertise<visualization_msgs::MarkerArray>("people/markers", 10)),
        picture_(nh.advertise<sensor_msgs::Image>("people/image", 2)),
        diagnostics_topic_(nh.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10)),
        live_(detector.pipeline(), {resolve_thread_count(o.threads)}, clock_,
              [this](const DepthFrame& f, PipelineFrame& r, std::int64_t) { publish(f, r); }) {
    // A compressed image the library's own PNG decoder leaves to OpenCV's codecs (a JPEG colour image, a PNG
    // outside its plain subset) needs them: opened before the first frame, whose latency would otherwise
    // hold their loading.
    if (o.compressed_depth || (o.colour && o.compressed_colour)) open_image_codecs();
    subscribe_depth(nh, o.compressed_depth);
    if (o.colour) subscribe_colour(nh, o.compressed_colour);
    timer_ = nh.createWallTimer(ros::WallDuration(o.diagnostics_period_s), [this, o](const ros::WallTimerEvent&) {
      diagnostics_topic_.publish(diagnostics_.report(live_.stats(), hardware_id_, o.diagnostics_period_s));
    });
  }

  std::string topics() const {
    return depth_topic_ + " with " + info_topic_ +
           (camera_info_ == CameraInfoPairing::latest ? " (the latest)" : " (by stamp)") +
           (colour_topic_.empty() ? "" : " and " + colour_topic_) +
           " -> " + people_.getTopic() + ", " + markers_.getTopic() + ", " + picture_.getTopic() + ", " +
           diagnostics_topic_.getTopic();
  }

  /// Stops the subscriptions, processes the frames still waiting and returns the summary line.
  std::string finish() {
    depth_with_info_.shutdown();
    depth_.shutdown();
    compressed_depth_.unsubscribe();
    compressed_info_.unsubscribe();
    depth_alone_.shutdown();
    info_.shutdown();
    colour_.shutdown();
    compressed_colour_.shutdown();
    timer_.stop();
    live_.finish();
    return diagnostics_.summary(live_.stats());
  }

 private:
  // Small messages (camera_info) are sent at once, not held back by Nagle's algorithm.
  static ros::TransportHints no_delay() { return ros::TransportHints().tcpNoDelay(); }
  static image_transport::TransportHints raw_no_delay() { return image_transport::TransportHints("raw", no_delay()); }

  // depth/image (raw or its compressedDepth subtopic) and its camera_info, by ~camera_info.
  void subscribe_depth(ros::NodeHandle& nh, bool compressed) {
    const std::string image_topic = nh.resolveName("depth/image");
    if (camera_info_ == CameraInfoPairing::exact && !compressed) {
      depth_with_info_ = transport_.subscribeCamera("depth/image", 2, &PeopleNode::on_depth<sensor_msgs::Image>, this, raw_no_delay());
      depth_topic_ = depth_with_info_.getTopic();
      info_topic_ = depth_with_info_.getInfoTopic();
    } else if (camera_info_ == CameraInfoPairing::exact) {  // compressed, with the camera_info of its stamp
      depth_topic_ = image_topic + "/compressedDepth";
      info_topic_ = image_transport::getCameraInfoTopic(image_topic);
      compressed_depth_.subscribe(nh, depth_topic_, 2, no_delay());
      compressed_info_.subscribe(nh, info_topic_, 2, no_delay());
      compressed_with_info_ = std::make_unique<CompressedWithInfo>(compressed_depth_, compressed_info_, 4);
      compressed_with_info_->registerCallback(&PeopleNode::on_depth<sensor_msgs::CompressedImage>, this);
    } else {
      if (compressed) {
        depth_topic_ = image_topic + "/compressedDepth";
        depth_alone_ = nh.subscribe(depth_topic_, 2, &PeopleNode::on_depth_alone<sensor_msgs::CompressedImage>, this, no_delay());
      } else {
        depth_ = transport_.subscribe("depth/image", 2, &PeopleNode::on_depth_alone<sensor_msgs::Image>, this, raw_no_delay());
        depth_topic_ = depth_.getTopic();
      }
      // depth/camera_info follows its image (as CameraSubscriber's does) unless it is remapped itself.
      const std::string remapped = nh.resolveName("depth/camera_info", true);
      info_topic_ = remapped != nh.resolveName("depth/camera_info", false)
                        ? remapped
                        : image_transport::getCameraInfoTopic(image_topic);
      info_ = nh.subscribe(info_topic_, 2, &PeopleNode::on_info, this, no_delay());
    }
  }

  // rgb/image (raw or its compressed subtopic).
  void subscribe_colour(ros::NodeHandle& nh, bool compressed) {
    if (compressed) {
      colour_topic_ = nh.resolveName("rgb/image") + "/compressed";
      compressed_colour_ = nh.subscribe(colour_topic_, 2, &PeopleNode::on_colour<sensor_msgs::CompressedImage>, this, no_delay());
    } else {
      colour_ = transport_.subscribe("rgb/image", 2, &PeopleNode::on_colour<sensor_msgs::Image>, this, raw_no_delay());
      colour_topic_ = colour_.getTopic();
    }
  }

  struct Arrival {
    std_msgs::Header header;
    std::int64_t received_us = 0;  ///< the depth message in the node
    std::int64_t complete_us = 0;  ///< the frame handed to the pipeline (its colour in, or none to wait for)
  };

  // ~camera_info latest: the newest camera_info is the camera model of the images after it (and of the one
  // waiting for the first).
  void on_info(const sensor_msgs::CameraInfoConstPtr& info) {
    latest_info_ = info;
    if (waiting_image_) waiting_image_(info);
    waiting_image_ = nullptr;
  }

  template <typename Message>
  void on_depth_alone(const boost::shared_ptr<const Message>& image) {
    if (latest_info_) {
      on_depth(image, latest_info_);
      return;
    }
    if (waiting_image_) {  // the newest image waits for the first camera_info
      diagnostics_.received();
      refuse(depth_topic_ + ": no camera_info received yet on " + info_topic_ + "; a newer depth image waits for it");
    } else {
      ROS_INFO("%s: waiting for the first camera_info on %s", depth_topic_.c_str(), info_topic_.c_str());
    }
    waiting_image_ = [this, image](const sensor_msgs::CameraInfoConstPtr& info) { on_depth(image, info); };
  }

  cv::Mat1w depth_of(const sensor_msgs::Image& image) const { return depth_mm_of(image, depth_topic_); }
  cv::Mat1w depth_of(const sensor_msgs::CompressedImage& image) const {
    return decode_compressed_depth(depth_topic_, image.format, image.data.data(), image.data.size());
  }
  cv::Mat3b colour_of(const sensor_msgs::Image& image) const { return bgr_of(image, colour_topic_); }
  cv::Mat3b colour_of(const sensor_msgs::CompressedImage& image) const {
    return decode_compressed_colour(colour_topic_, image.format, image.data.data(), image.data.size());
  }

  template <typename Message>
  void on_depth(const boost::shared_ptr<const Message>& image, const sensor_msgs::CameraInfoConstPtr& info) {
    const std::int64_t received_us = clock_.now_us();
    diagnostics_.received();
    hardware_id_ = image->header.frame_id;
    DepthFrame frame;
    try {
      frame.depth_mm = depth_of(*image);
      // Stamped apart, a camera_info must at least be of the image's optical frame (not the IR camera's for a
      // depth image registered to colour).
      if (camera_info_ == CameraInfoPairing::latest && !info->header.frame_id.empty() &&
          !image->header.frame_id.empty() && info->header.frame_id != image->header.frame_id) {
        fail(info_topic_, "camera_info of frame '" + info->header.frame_id + "' for a depth image of frame '" +
                              image->header.frame_id + "' (remap depth/camera_info to the camera_info of the depth image's frame)");
      }
      frame.camera = camera_model_of(*info, frame.depth_mm.cols, frame.depth_mm.rows, info_topic_);
      // A background model of the room (~background) of another size or camera: the frame is refused here.
      const auto& background = detector_.params().analyser.background;
      if (background) background->check_fits(frame);
    } catch (const Error& e) {
      refuse(e.what());
      return;
    }
    frame.index = next_index_++;
    frame.timestamp_us = time_us(image->header.stamp);
    frame.name = std::to_string(image->header.stamp.sec) + "." + std::to_string(image->header.stamp.nsec);
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      arrivals_[frame.index] = {image->header, received_us};
    }
    if (!colour_topic_.empty()) {
      go_on(pairing_.add_depth(std::move(frame)));
    } else {
      go_on({{std::move(frame), -1}});
    }
  }

  template <typename Message>
  void on_colour(const boost::shared_ptr<const Message>& image) {
    cv::Mat3b bgr;
    try {
      bgr = colour_of(*image);
    } catch (const Error& e) {
      refuse(e.what());
      return;
    }
    go_on(pairing_.add_colour(time_us(image->header.stamp), std::move(bgr)));
  }

  void go_on(std::vector<PairedFrame> frames) {
    const std::int64_t now_us = clock_.now_us();
    for (PairedFrame& p : frames) {
      if (!p.frame.bgr.empty() && p.frame.bgr.size() != p.frame.depth_mm.size()) {
        refuse(colour_topic_ + ": colour image of " + std::to_string(p.frame.bgr.cols) + "x" +
               std::to_string(p.frame.bgr.rows) + " is not registered to the depth image of " +
               std::to_string(p.frame.depth_mm.cols) + "x" + std::to_string(p.frame.depth_mm.rows) +
               " (use a depth image aligned to colour); frame used without colour");
        p.frame.bgr.release();
        p.gap_us = -1;
      }
      diagnostics_.paired(p.gap_us);
      {
        const std::lock_guard<std::mutex> lock(mutex_);
        arrivals_[p.frame.index].complete_us = now_us;
      }
      live_.push(std::move(p.frame));
    }
  }

  void refuse(const std::string& reason) {
    diagnostics_.refused(reason);
    ROS_WARN_THROTTLE(5.0, "%s", reason.c_str());
  }

  // A processed frame (a live worker, frames in arrival order): its people out, as soon as possible.
  void publish(const DepthFrame& frame, PipelineFrame& result) {
    Arrival arrival;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      arrival = arrivals_[frame.index];
      arrivals_.erase(arrivals_.begin(), arrivals_.upper_bound(frame.index));  // this one and dropped ones
    }
    const rdsf_people::People people =
        people_message(arrival.header, detector_.detections(frame, result), result.analysis.candidates.size());
    people_.publish(people);
    const std::int64_t now_us = clock_.now_us();
    diagnostics_.published(static_cast<double>(now_us - arrival.received_us) / 1000.0,
                           static_cast<double>(now_us - arrival.complete_us) / 1000.0);
    markers_.publish(people_markers(people, frame.camera));
    // rdsf-detect --save-dir's picture of the frame, drawn only while someone watches (rqt_image_view): a few
    // milliseconds on this worker, after the people are out.
    if (picture_.getNumSubscribers() > 0) {
      picture_.publish(
          cv_bridge::CvImage(arrival.header, "bgr8", render_people(frame, result, detector_.pipeline().tracker())).toImageMsg());
    }
  }

  PeopleDetector& detector_;
  const SteadyClock clock_;
  ColourPairing pairing_;
  NodeDiagnostics diagnostics_;
  image_transport::ImageTransport transport_;
  const CameraInfoPairing camera_info_;
  using CompressedWithInfo = message_filters::TimeSynchronizer<sensor_msgs::CompressedImage, sensor_msgs::CameraInfo>;
  image_transport::CameraSubscriber depth_with_info_;  ///< exact, raw
  message_filters::Subscriber<sensor_msgs::CompressedImage> compressed_depth_;  ///< exact, compressed
  message_filters::Subscriber<sensor_msgs::CameraInfo> compressed_info_;       ///< exact, compressed
  std::unique_ptr<CompressedWithInfo> compressed_with_info_;                    ///< exact, compressed
  image_transport::Subscriber depth_;                  ///< latest, raw
  ros::Subscriber depth_alone_;                        ///< latest, compressed
  ros::Subscriber info_;                               ///< latest
  std::string depth_topic_, info_topic_, colour_topic_;  ///< colour_topic_ empty: no colour
  sensor_msgs::CameraInfoConstPtr latest_info_;  ///< latest: the newest camera_info
  /// latest: the newest image before the first camera_info, waiting for it
  std::function<void(const sensor_msgs::CameraInfoConstPtr&)> waiting_image_;
  image_transport::Subscriber colour_;  ///< raw
  ros::Subscriber compressed_colour_;   ///< compressed
  ros::Publisher people_, markers_, picture_, diagnostics_topic_;
  ros::WallTimer timer_;
  std::string hardware_id_;
  std::int64_t next_index_ = 0;
  std::mutex mutex_;
  std::map<std::int64_t, Arrival> arrivals_;  ///< frames pushed and not yet published, by index
  LivePipeline live_;  ///< last: destroyed first (its destructor may still publish waiting frames)
};

}  // namespace

int run_people_node(const PeopleNodeOptions& o) {
  BoostedModel model = BoostedModel::load(o.model, o.models_dir);
  // The model's feature spec unless --feature-spec names one (PeoplePipeline then checks they agree).
  const PipelineParams params = o.feature_spec_given ? o.pipeline : PeopleDetector::params_for(model, o.pipeline);
  const std::string label = model_label(model) + " (" + model.path() + "), " + params.decision_text(model);
  PeopleDetector detector(std::move(model), params);
  ros::NodeHandle nh;
  PeopleNode node(nh, detector, o);
  std::cerr << "rdsf_people: model " << label << "; " << resolve_thread_count(o.threads) << " live worker(s); "
            << node.topics() << "\n";
  ros::spin();  // until Ctrl-C or rosnode kill (ros::shutdown)
  std::cerr << "rdsf_people: " << node.finish() << "\n";
  return 0;
}

}  // namespace rdsf
