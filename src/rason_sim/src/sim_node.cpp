// rason_sim_node: two (or more) Kobuki-like robots and a Kinect-like camera in MuJoCo,
// publishing what kobuki_node and freenect publish. See README.md for topics and params.
#include <geometry_msgs/Pose2D.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/Twist.h>
#include <mujoco/mujoco.h>
#include <nav_msgs/Odometry.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <rason_msgs/RobotSightings.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/PointCloud2.h>
#include <tf2_msgs/TFMessage.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "rason_sim/camera_messages.h"
#include "rason_sim/camera_worker.h"
#include "rason_sim/depth_camera.h"
#include "rason_sim/mjcf_model.h"
#include "rason_sim/diff_drive.h"
#include "rason_sim/frames.h"
#include "rason_sim/lockstep_acks.h"
#include "rason_sim/pacing.h"
#include "rason_sim/params.h"
#include "rason_sim/world.h"

namespace rason_sim {
namespace {

// ---- one simulated robot ----------------------------------------------------------------

struct Robot {
  RobotConfig config;
  int root_qpos = -1, root_qvel = -1, body = -1, camera = -1, camera_slot = -1;
  int left_qpos = -1, right_qpos = -1, left_dof = -1, right_dof = -1;
  int left_motor = -1, right_motor = -1;
  double left_integral = 0.0, right_integral = 0.0;  // servo's integral term (rad)
  WheelOdometry odometry;
  double linear = 0.0, angular = 0.0, last_command = -1e9;
  bool teleport = false;
  geometry_msgs::Pose2D teleport_pose;
  ros::Subscriber cmd_vel_sub, set_pose_sub, frame_ack_sub, odom_ack_sub, control_ack_sub;
  StampAck frame_ack, odom_ack;
  std::unique_ptr<ControlAck> control_ack;  // with lockstep and a ~control_ack_topic
  ros::Publisher odom_pub, true_pose_pub, image_pub, depth_pub, cloud_pub, info_pub;
  geometry_msgs::TransformStamped world_to_odom;

  Robot(const RobotConfig& c, const BaseGeometry& base) : config(c), odometry(base) {}
};

int requireId(const mjModel* m, mjtObj type, const std::string& name) {
  const int id = mj_name2id(m, type, name.c_str());
  if (id < 0) throw std::runtime_error("MuJoCo model has no '" + name + "'");
  return id;
}

class Simulator {
 public:
  Simulator(ros::NodeHandle& nh, ros::NodeHandle& pnh)
      : params_(simParamsFrom(ParamReader([&pnh](const std::string& key, XmlRpc::XmlRpcValue& value) {
          return pnh.getParam(key, value);
        }))),
        world_(params_.world),
        lockstep_pace_(params_.camera_rate, params_.max_lockstep_factor) {
    rng_.reseed(static_cast<uint64_t>(params_.seed));
    loadModel();
    intrinsics_ = intrinsicsFor(world_.camera);
    clock_pub_ = nh.advertise<rosgraph_msgs::Clock>("/clock", 10);
    tf_pub_ = nh.advertise<tf2_msgs::TFMessage>("/tf", 100);
    tf_static_pub_ = nh.advertise<tf2_msgs::TFMessage>("/tf_static", 1, true);
    for (const RobotConfig& config : world_.robots) setUpRobot(nh, config);
    if (params_.lockstep) {
      ack_spinner_.reset(new ros::AsyncSpinner(1, &ack_queue_));
      ack_spinner_->start();
    }
    publishStaticTransforms();
    if (params_.lockstep)
      ROS_INFO("rason_sim: %zu robots, real-time factor %.2f (0 = as fast as possible), seed %d; "
               "lockstep: each camera frame waits for <robot>/%s of the one before (at factor 0 "
               "at most %.1fx real time)%s%s%s", robots_.size(), params_.real_time_factor, params_.seed,
               params_.frame_ack_topic.c_str(), params_.max_lockstep_factor,
               params_.control_ack_topic.empty() ? "" : "; a moving robot's controller ticks (<robot>/",
               params_.control_ack_topic.c_str(),
               params_.control_ack_topic.empty() ? "" : ") are waited for");
    else
      ROS_INFO("rason_sim: %zu robots, real-time factor %.2f (0 = as fast as possible), seed %d",
               robots_.size(), params_.real_time_factor, params_.seed);
  }

  ~Simulator() {
    if (ack_spinner_) ack_spinner_->stop();
    camera_worker_.reset();
    if (data_) mj_deleteData(data_);
    if (model_) mj_deleteModel(model_);
  }

  void run() {
    const double control_period = 1.0 / params_.clock_rate;
    const int substeps = std::max(1, static_cast<int>(std::lround(control_period / model_->opt.timestep)));
    const auto wall_start = WallClock::now();
    WallPacer pacer(params_.real_time_factor, wall_start);
    auto step_wall = wall_start;
    double next_odom = 0.0, next_camera = 0.0;
    while (ros::ok()) {
      ros::spinOnce();
      const double now = data_->time;
      for (auto& robot : robots_) {
        if (robot->control_ack) awaitControlTick(*robot, now);
        applyCommands(*robot, now, substeps * model_->opt.timestep);
      }
      for (int i = 0; i < substeps; ++i) mj_step(model_, data_);
      const double t = data_->time;
      // odometry before the clock: with lockstep, a controller tick that the clock at t sets
      // off reads the odometry of t, at any pace
      if (t >= next_odom) {
        publishOdometry(t);
        if (params_.lockstep)
          for (auto& robot : robots_) awaitOdometryRelayed(*robot);
        next_odom += 1.0 / params_.odom_rate;
        if (next_odom < t) next_odom = t;  // never try to catch up with a burst
      }
      rosgraph_msgs::Clock clock;
      clock.clock = ros::Time(t);
      clock_pub_.publish(clock);
      if (t >= next_camera) {
        for (auto& robot : robots_) {
          if (robot->camera_slot < 0) continue;
          camera_worker_->waitIdle(robot->camera_slot);  // its last frame is out
          if (params_.lockstep) awaitFrameDone(*robot);
          submitCamera(*robot, t);
        }
        next_camera += 1.0 / params_.camera_rate;
        if (next_camera < t) next_camera = t;
      }
      if (params_.max_sim_time > 0.0 && t >= params_.max_sim_time) break;
      if (params_.lockstep && params_.real_time_factor == 0.0 && hasCamera()) {
        // Not flat out between frames: a burst of simulated time while the frame is being
        // processed would leave the controllers and agents (wall-clock CPU) behind the world
        // as much as a lagging camera did. A step takes its share of the wall time a frame
        // needs; until every camera's consumer is up (nodes starting), about real time.
        std::this_thread::sleep_until(
            step_wall + wallSeconds(lockstep_pace_.stepWallSeconds(control_period, framesConsumed())));
        step_wall = WallClock::now();
      } else if (params_.real_time_factor > 0.0) {
        const double dropped = pacer.wait(t);
        if (dropped > 0.0)
          ROS_WARN_THROTTLE(10.0, "rason_sim: the CPU cannot keep up with real-time factor %.2f; "
                            "%.1f s of wall time lost so far are not caught up (the simulation "
                            "runs slower instead of in bursts)", params_.real_time_factor, pacer.lost());
      }
    }
    const double wall = std::chrono::duration<double>(WallClock::now() - wall_start).count();
    ROS_INFO("rason_sim: simulated %.1f s in %.1f s wall time (real-time factor %.2f; %.1f s of "
             "wall time lost to a busy CPU)", data_->time, wall, wall > 0 ? data_->time / wall : 0.0,
             pacer.lost());
  }

 private:
  void loadModel() {
    model_ = compileMjcf(buildMjcf(world_));
    data_ = mj_makeData(model_);
    mj_forward(model_, data_);
    const int cameras = static_cast<int>(std::count_if(world_.robots.begin(), world_.robots.end(),
                                                       [](const RobotConfig& r) { return r.camera; }));
    if (cameras > 0)
      camera_worker_.reset(new CameraWorker(model_, world_.camera.width, world_.camera.height, cameras));
  }

  void setUpRobot(ros::NodeHandle& nh, const RobotConfig& config) {
    auto robot = std::make_shared<Robot>(config, world_.base);
    const std::string& n = config.name;
    robot->world_to_odom = worldToOdom(n, config.start, robot->odometry);
    const int root = requireId(model_, mjOBJ_JOINT, rootJointName(n));
    robot->root_qpos = model_->jnt_qposadr[root];
    robot->root_qvel = model_->jnt_dofadr[root];
    robot->body = requireId(model_, mjOBJ_BODY, n);
    robot->left_qpos = model_->jnt_qposadr[requireId(model_, mjOBJ_JOINT, wheelJointName(n, true))];
    robot->right_qpos = model_->jnt_qposadr[requireId(model_, mjOBJ_JOINT, wheelJointName(n, false))];
    robot->left_dof = model_->jnt_dofadr[requireId(model_, mjOBJ_JOINT, wheelJointName(n, true))];
    robot->right_dof = model_->jnt_dofadr[requireId(model_, mjOBJ_JOINT, wheelJointName(n, false))];
    robot->left_motor = requireId(model_, mjOBJ_ACTUATOR, wheelActuatorName(n, true));
    robot->right_motor = requireId(model_, mjOBJ_ACTUATOR, wheelActuatorName(n, false));
    Robot* raw = robot.get();
    robot->cmd_vel_sub = nh.subscribe<geometry_msgs::Twist>(
        n + "/cmd_vel", 10, [this, raw](const geometry_msgs::Twist::ConstPtr& msg) { onCmdVel(*raw, *msg); });
    robot->set_pose_sub = nh.subscribe<geometry_msgs::Pose2D>(
        n + "/set_pose", 10, [raw](const geometry_msgs::Pose2D::ConstPtr& msg) {
          if (std::isfinite(msg->x) && std::isfinite(msg->y) && std::isfinite(msg->theta)) {
            raw->teleport = true;
            raw->teleport_pose = *msg;
          } else {
            ROS_WARN("rason_sim: ignoring set_pose with a non-finite value for %s", raw->config.name.c_str());
          }
        });
    robot->odom_pub = nh.advertise<nav_msgs::Odometry>(n + "/odom", 50);
    robot->true_pose_pub = nh.advertise<geometry_msgs::PoseStamped>(n + "/true_pose", 50);
    if (config.camera) {
      robot->camera = requireId(model_, mjOBJ_CAMERA, cameraName(n));
      robot->camera_slot = cameras_set_up_++;
      robot->image_pub = nh.advertise<sensor_msgs::Image>(n + "/camera/rgb/image_raw", 2);
      robot->depth_pub = nh.advertise<sensor_msgs::Image>(n + "/camera/depth_registered/image_raw", 2);
      robot->cloud_pub = nh.advertise<sensor_msgs::PointCloud2>(n + "/camera/depth_registered/points", 2);
      robot->info_pub = nh.advertise<sensor_msgs::CameraInfo>(n + "/camera/rgb/camera_info", 2);
      if (params_.lockstep)
        robot->frame_ack_sub = subscribeReports<rason_msgs::RobotSightings>(
            nh, n + "/" + params_.frame_ack_topic, 10,
            [raw](const rason_msgs::RobotSightings::ConstPtr& msg) { raw->frame_ack.onDone(msg->header.stamp.toSec()); });
    }
    if (params_.lockstep && !params_.odom_ack_topic.empty())
      robot->odom_ack_sub = subscribeReports<nav_msgs::Odometry>(
          nh, n + "/" + params_.odom_ack_topic, 50,
          [raw](const nav_msgs::Odometry::ConstPtr& msg) { raw->odom_ack.onDone(msg->header.stamp.toSec()); });
    if (params_.lockstep && !params_.control_ack_topic.empty()) {
      robot->control_ack.reset(new ControlAck(1.0 / params_.control_rate));
      ControlAck* ack = robot->control_ack.get();
      robot->control_ack_sub = subscribeReports<nav_msgs::Odometry>(
          nh, n + "/" + params_.control_ack_topic, 50, [ack](const nav_msgs::Odometry::ConstPtr& msg) {
            const auto& v = msg->twist.twist;
            ack->onTick(msg->header.stamp.toSec(), v.linear.x != 0.0 || v.angular.z != 0.0);
          });
    }
    robots_.push_back(robot);
  }

  // Lockstep's reports are served on a thread of their own (ack_spinner_), so they come in
  // while the simulation loop waits for them.
  template <typename M>
  ros::Subscriber subscribeReports(ros::NodeHandle& nh, const std::string& topic, uint32_t queue,
                                   const boost::function<void(const typename M::ConstPtr&)>& callback) {
    auto options = ros::SubscribeOptions::create<M>(topic, queue, callback, ros::VoidPtr(), &ack_queue_);
    return nh.subscribe(options);
  }

  void onCmdVel(Robot& robot, const geometry_msgs::Twist& msg) {
    if (!std::isfinite(msg.linear.x) || !std::isfinite(msg.angular.z)) {
      ROS_WARN_THROTTLE(5.0, "rason_sim: %s/cmd_vel with a non-finite value ignored", robot.config.name.c_str());
      return;
    }
    robot.linear = msg.linear.x;
    robot.angular = msg.angular.z;
    robot.last_command = data_->time;
  }

  void applyCommands(Robot& robot, double now, double dt) {
    if (robot.teleport) {
      robot.teleport = false;
      double* q = data_->qpos + robot.root_qpos;
      q[0] = robot.teleport_pose.x;
      q[1] = robot.teleport_pose.y;
      q[2] = 0.0;
      q[3] = std::cos(robot.teleport_pose.theta / 2.0);
      q[4] = q[5] = 0.0;
      q[6] = std::sin(robot.teleport_pose.theta / 2.0);
      for (int i = 0; i < 6; ++i) data_->qvel[robot.root_qvel + i] = 0.0;
      mj_forward(model_, data_);
      const Pose2D moved{robot.teleport_pose.x, robot.teleport_pose.y, robot.teleport_pose.theta};
      robot.world_to_odom = worldToOdom(robot.config.name, moved, robot.odometry);
      publishStaticTransforms();
    }
    // Like kobuki_node, stop when commands stop arriving.
    const bool fresh = now - robot.last_command <= params_.cmd_vel_timeout;
    const WheelSpeeds speeds = groundSpeeds(
        wheelSpeedsFor(fresh ? robot.linear : 0.0, fresh ? robot.angular : 0.0, world_.base),
        robot.config.slip);
    data_->ctrl[robot.left_motor] =
        servoSetPoint(speeds.left, data_->qvel[robot.left_dof], robot.left_integral, dt);
    data_->ctrl[robot.right_motor] =
        servoSetPoint(speeds.right, data_->qvel[robot.right_dof], robot.right_integral, dt);
  }

  void publishOdometry(double t) {
    const ros::Time stamp(t);
    tf2_msgs::TFMessage tf;
    for (auto& robot : robots_) {
      Robot& r = *robot;
      r.odometry.update(encoderAngle(data_->qpos[r.left_qpos], r.config.slip.left),
                        encoderAngle(data_->qpos[r.right_qpos], r.config.slip.right), t);
      nav_msgs::Odometry odom;
      odom.header.stamp = stamp;
      odom.header.frame_id = r.config.name + "/odom";
      odom.child_frame_id = r.config.name + "/base_footprint";
      odom.pose.pose.position.x = r.odometry.x();
      odom.pose.pose.position.y = r.odometry.y();
      odom.pose.pose.orientation = yawQuaternion(r.odometry.yaw());
      odom.twist.twist.linear.x = r.odometry.linear();
      odom.twist.twist.angular.z = r.odometry.angular();
      for (int i : {0, 7, 35}) odom.pose.covariance[i] = 0.1;  // x, y, yaw (kobuki_node's values)
      for (int i : {14, 21, 28}) odom.pose.covariance[i] = 1e6;  // not measured
      r.odom_pub.publish(odom);

      geometry_msgs::TransformStamped transform;
      transform.header = odom.header;
      transform.child_frame_id = odom.child_frame_id;
      transform.transform.translation.x = r.odometry.x();
      transform.transform.translation.y = r.odometry.y();
      transform.transform.rotation = odom.pose.pose.orientation;
      tf.transforms.push_back(transform);

      geometry_msgs::PoseStamped truth;
      truth.header.stamp = stamp;
      truth.header.frame_id = "world";
      const double* p = data_->xpos + 3 * r.body;
      const double* q = data_->xquat + 4 * r.body;
      truth.pose.position.x = p[0];
      truth.pose.position.y = p[1];
      truth.pose.position.z = p[2];
      truth.pose.orientation.w = q[0];
      truth.pose.orientation.x = q[1];
      truth.pose.orientation.y = q[2];
      truth.pose.orientation.z = q[3];
      r.true_pose_pub.publish(truth);
    }
    tf_pub_.publish(tf);
  }

  bool hasCamera() const {
    for (const auto& robot : robots_)
      if (robot->camera >= 0) return true;
    return false;
  }

  // True when every robot with a camera has a consumer reporting its frames done.
  bool framesConsumed() const {
    for (const auto& robot : robots_)
      if (robot->camera >= 0 && robot->frame_ack_sub.getNumPublishers() == 0) return false;
    return true;
  }

  // Lockstep: the next frame waits (wall clock, up to ~frame_ack_timeout) until the consumer
  // has reported the last one done, so a fast simulation never leaves the camera pipeline,
  // and the agents reading it, behind the world: seen in simulated time, a frame takes at
  // most one camera period to process at any speed.
  void awaitFrameDone(Robot& robot) {
    const double took = robot.frame_ack.awaitDone(params_.frame_ack_timeout);
    if (took > 0.0) {
      lockstep_pace_.onFrameProcessed(took);  // the pace for the next period
    } else if (took < 0.0) {
      ROS_WARN_THROTTLE(10.0, "rason_sim: no %s/%s for the frame within %.1f s (wall); going on "
                        "without it", robot.config.name.c_str(), params_.frame_ack_topic.c_str(),
                        params_.frame_ack_timeout);
    }
  }

  // Lockstep: the odometry just published waits (up to ~control_ack_timeout) until the node
  // that relays it to the controller (the fault injector's odom_filtered) has passed it on,
  // so that a busy CPU never leaves the controller steering by an old pose.
  void awaitOdometryRelayed(Robot& robot) {
    if (robot.odom_ack_sub.getNumPublishers() == 0) return;
    robot.odom_ack.onSent(data_->time);
    if (robot.odom_ack.awaitDone(params_.control_ack_timeout) < 0.0)
      ROS_WARN_THROTTLE(10.0, "rason_sim: no %s/%s for the odometry at %.2f s within %.1f s "
                        "(wall); going on without it", robot.config.name.c_str(),
                        params_.odom_ack_topic.c_str(), data_->time, params_.control_ack_timeout);
  }

  // Lockstep with the robot's controller (control_ticks.h): before stepping from now, wait
  // (wall clock, up to ~control_ack_timeout) for a tick that is due, and after a tick that
  // stopped the robot, for the zero twist to reach the base (through the fault injector).
  void awaitControlTick(Robot& robot, double now) {
    ControlAck& ack = *robot.control_ack;
    const auto deadline = WallClock::now() + wallSeconds(params_.control_ack_timeout);
    double due = 0.0;
    if (!ack.awaitTick(now, deadline, &due)) {
      ROS_WARN_THROTTLE(10.0, "rason_sim: no %s/%s for the control tick due at %.2f s within %.1f s "
                        "(wall); going on without waiting for that controller until it reports a "
                        "motion again", robot.config.name.c_str(), params_.control_ack_topic.c_str(),
                        due, params_.control_ack_timeout);
      return;
    }
    if (!ack.stopPending()) return;
    // cmd_vel is served by the global queue, which this loop spins
    while (robot.linear != 0.0 || robot.angular != 0.0) {
      if (WallClock::now() >= deadline) {
        ROS_WARN_THROTTLE(10.0, "rason_sim: %s's controller stopped it at %.2f s, but no zero "
                          "%s/cmd_vel came within %.1f s (wall); going on", robot.config.name.c_str(),
                          now, robot.config.name.c_str(), params_.control_ack_timeout);
        break;
      }
      ros::getGlobalCallbackQueue()->callAvailable(ros::WallDuration(0.001));
    }
    ack.stopReached();
  }

  // Robot's camera at t to the camera worker, which renders and publishes it (publishFrame);
  // nothing when nobody looks, as rendering is the costly part.
  void submitCamera(Robot& robot, double t) {
    const bool cloud_wanted = robot.cloud_pub.getNumSubscribers() > 0;
    const bool wanted = cloud_wanted || robot.image_pub.getNumSubscribers() > 0 ||
                        robot.depth_pub.getNumSubscribers() > 0;
    if (!wanted) return;
    Robot* raw = &robot;
    camera_worker_->submit(robot.camera_slot, model_, data_, robot.camera,
                           [this, raw, t, cloud_wanted](const std::vector<unsigned char>& rgb,
                                                         const std::vector<float>& depth, double near, double far) {
                             publishFrame(*raw, t, cloud_wanted, rgb, depth, near, far);
                           });
  }

  // On the camera worker's thread: the images of a rendered frame, published; with lockstep
  // and a consumer, the frame is then waited for (awaitFrameDone).
  void publishFrame(Robot& robot, double t, bool cloud_wanted, const std::vector<unsigned char>& rgb,
                    const std::vector<float>& depth, double near, double far) {
    sensor_msgs::Image image;
    sensor_msgs::PointCloud2 cloud;
    buildFrame(intrinsics_, rgb.data(), depth.data(), near, far, params_.noise, rng_, image.data, depth_mm_,
               cloud_wanted ? &cloud.data : nullptr);
    std_msgs::Header header;
    header.stamp = ros::Time(t);
    header.frame_id = robot.config.name + "/camera_rgb_optical_frame";
    describeImage(intrinsics_, header, image);
    robot.image_pub.publish(image);
    if (robot.depth_pub.getNumSubscribers() > 0)
      robot.depth_pub.publish(depthImage(intrinsics_, header, depth_mm_));
    if (cloud_wanted) {
      describeCloud(intrinsics_, header, cloud);
      robot.cloud_pub.publish(cloud);
    }
    robot.info_pub.publish(cameraInfo(intrinsics_, header));
    if (params_.lockstep && robot.frame_ack_sub.getNumPublishers() > 0) robot.frame_ack.onSent(t);
  }

  // /tf_static is latched: every message carries all static transforms.
  void publishStaticTransforms() {
    tf2_msgs::TFMessage tf;
    for (auto& robot : robots_) tf.transforms.push_back(robot->world_to_odom);
    for (auto& robot : robots_)
      if (robot->camera >= 0) tf.transforms.push_back(baseToOpticalFrame(robot->config.name, world_.camera));
    tf_static_pub_.publish(tf);
  }

  const SimParams params_;
  const WorldConfig& world_;
  ros::CallbackQueue ack_queue_;  // lockstep's reports, served by ack_spinner_
  std::unique_ptr<ros::AsyncSpinner> ack_spinner_;
  LockstepPace lockstep_pace_;  // at factor 0 with lockstep
  PixelNoise rng_;  // the camera worker's
  mjModel* model_ = nullptr;
  mjData* data_ = nullptr;
  std::unique_ptr<CameraWorker> camera_worker_;  // with a camera in the world
  int cameras_set_up_ = 0;
  Intrinsics intrinsics_;
  std::vector<uint16_t> depth_mm_;  // the camera worker's
  std::vector<std::shared_ptr<Robot>> robots_;
  ros::Publisher clock_pub_, tf_pub_, tf_static_pub_;
};

}  // namespace
}  // namespace rason_sim

int main(int argc, char** argv) {
  ros::init(argc, argv, "rason_sim");
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  try {
    rason_sim::Simulator simulator(nh, pnh);
    simulator.run();
  } catch (const std::exception& e) {
    ROS_FATAL("rason_sim: %s", e.what());
    return 1;
  }
  return 0;
}
