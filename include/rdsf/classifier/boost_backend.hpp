#pragma once
// Which boosting implementation trains a model: an enum inside the library, a name at its edges (recipes,
// --backend, the model file's training.backend). A name that is not known is kept as given, so that
// validate_training_params can refuse it with the name in the message.
#include <string>

namespace rdsf {

class BoostBackend {
 public:
  enum Kind {
    native,   ///< Real AdaBoost with look-up tables (real_adaboost.hpp)
    opencv,   ///< cv::ml::Boost REAL stumps (opencv_boost.hpp)
    unknown,  ///< a name that is neither
  };
  BoostBackend(Kind kind = native) : kind_(kind) {}  // NOLINT: a Kind is a backend
  /// "native" or "opencv"; anything else is unknown (and keeps its name for the message).
  BoostBackend(const std::string& name);  // NOLINT: recipes and options give names
  BoostBackend(const char* name) : BoostBackend(std::string(name)) {}  // NOLINT

  Kind kind() const { return kind_; }
  /// "native", "opencv", or the unknown name as given.
  std::string name() const;
  bool operator==(Kind kind) const { return kind_ == kind; }
  bool operator!=(Kind kind) const { return kind_ != kind; }

 private:
  Kind kind_ = native;
  std::string unknown_name_;
};

}  // namespace rdsf
