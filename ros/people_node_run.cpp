#include "ros/people_node_run.hpp"

#include <iostream>
#include <map>
#include <mutex>

#include <image_transport/camera_common.h>
#include <image_transport/image_transport.h>
#include <ros/ros.h>

#include "rdsf/core/clock.hpp"
#include "rdsf/core/error.hpp"
#include "rdsf/core/thread_count.hpp"
#include "rdsf/pipeline/live_pipeline.hpp"
#include "rdsf/pipeline/people_detector.hpp"
#include "ros/colour_pairing.hpp"
#include "ros/image_frames.hpp"
#include "ros/node_diagnostics.hpp"
#include "ros/people_messages.hpp"

namespace rdsf {
namespace {

// The node's subscriptions, publishers and live pipeline. Callbacks run on ros::spin's thread; frames are
// analysed and published on the live pipeline's workers, one frame at a time in arrival order. A depth image
// meets its camera_info by exact stamp (CameraSubscriber) or, with ~camera_info latest, takes the newest
// camera_info received (its own subscription; before the first one the newest image waits for it).
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
        diagnostics_topic_(nh.advertise<diagnostic_msgs::DiagnosticArray>("/diagnostics", 10)),
        live_(detector.pipeline(), {resolve_thread_count(o.threads)}, clock_,
              [this](const DepthFrame& f, PipelineFrame& r, std::int64_t) { publish(f, r); }) {
    // Small messages (camera_info) are sent at once, not held back by Nagle's algorithm.
    const image_transport::TransportHints hints("raw", ros::TransportHints().tcpNoDelay());
    if (camera_info_ == CameraInfoPairing::exact) {
      depth_with_info_ = transport_.subscribeCamera("depth/image", 2, &PeopleNode::on_depth, this, hints);
      depth_topic_ = depth_with_info_.getTopic();
      info_topic_ = depth_with_info_.getInfoTopic();
    } else {
      depth_ = transport_.subscribe("depth/image", 2, &PeopleNode::on_depth_alone, this, hints);
      depth_topic_ = depth_.getTopic();
      // depth/camera_info follows its image (as CameraSubscriber's does) unless it is remapped itself.
      const std::string remapped = nh.resolveName("depth/camera_info", true);
      info_topic_ = remapped != nh.resolveName("depth/camera_info", false)
                        ? remapped
                        : image_transport::getCameraInfoTopic(depth_topic_);
      info_ = nh.subscribe(info_topic_, 2, &PeopleNode::on_info, this, ros::TransportHints().tcpNoDelay());
    }
    if (o.colour) colour_ = transport_.subscribe("rgb/image", 2, &PeopleNode::on_colour, this, hints);
    timer_ = nh.createWallTimer(ros::WallDuration(o.diagnostics_period_s), [this, o](const ros::WallTimerEvent&) {
      diagnostics_topic_.publish(diagnostics_.report(live_.stats(), hardware_id_, o.diagnostics_period_s));
    });
  }

  std::string topics() const {
    return depth_topic_ + " with " + info_topic_ +
           (camera_info_ == CameraInfoPairing::latest ? " (the latest)" : " (by stamp)") +
           (colour_ ? " and " + colour_.getTopic() : "") +
           " -> " + people_.getTopic() + ", " + markers_.getTopic() + ", " + diagnostics_topic_.getTopic();
  }

  /// Stops the subscriptions, processes the frames still waiting and returns the summary line.
  std::string finish() {
    depth_with_info_.shutdown();
    depth_.shutdown();
    info_.shutdown();
    colour_.shutdown();
    timer_.stop();
    live_.finish();
    return diagnostics_.summary(live_.stats());
  }

 private:
  struct Arrival {
    std_msgs::Header header;
    std::int64_t received_us = 0;  ///< the depth message in the node
    std::int64_t complete_us = 0;  ///< the frame handed to the pipeline (its colour in, or none to wait for)
  };

  // ~camera_info latest: the newest camera_info is the camera model of the images after it (and of the one
  // waiting for the first).
  void on_info(const sensor_msgs::CameraInfoConstPtr& info) {
    latest_info_ = info;
    if (waiting_image_) on_depth(std::move(waiting_image_), info);
    waiting_image_.reset();
  }

  void on_depth_alone(const sensor_msgs::ImageConstPtr& image) {
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
    waiting_image_ = image;
  }

  void on_depth(const sensor_msgs::ImageConstPtr& image, const sensor_msgs::CameraInfoConstPtr& info) {
    const std::int64_t received_us = clock_.now_us();
    diagnostics_.received();
    hardware_id_ = image->header.frame_id;
    DepthFrame frame;
    try {
      frame.depth_mm = depth_mm_of(*image, depth_topic_);
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
    if (colour_) {
      go_on(pairing_.add_depth(std::move(frame)));
    } else {
      go_on({{std::move(frame), -1}});
    }
  }

  void on_colour(const sensor_msgs::ImageConstPtr& image) {
    cv::Mat3b bgr;
    try {
      bgr = bgr_of(*image, colour_.getTopic());
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
        refuse(colour_.getTopic() + ": colour image of " + std::to_string(p.frame.bgr.cols) + "x" +
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
  }

  PeopleDetector& detector_;
  const SteadyClock clock_;
  ColourPairing pairing_;
  NodeDiagnostics diagnostics_;
  image_transport::ImageTransport transport_;
  const CameraInfoPairing camera_info_;
  image_transport::CameraSubscriber depth_with_info_;  ///< exact
  image_transport::Subscriber depth_;                  ///< latest
  ros::Subscriber info_;                               ///< latest
  std::string depth_topic_, info_topic_;
  sensor_msgs::CameraInfoConstPtr latest_info_;  ///< latest: the newest camera_info
  sensor_msgs::ImageConstPtr waiting_image_;     ///< latest: the newest image before the first camera_info
  image_transport::Subscriber colour_;
  ros::Publisher people_, markers_, diagnostics_topic_;
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
