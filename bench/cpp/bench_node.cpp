// The roscpp side of bench/bench_roscpp.py: the same workers as the Python scripts of
// bench/bench_pubsub.py, written against roscpp, taking the same arguments and printing the
// same JSON, so that C++ nodes run in the same rounds as rospy and rosx (and with them, in the
// mixed pairs). Built by the bench itself against Debian's libroscpp-dev.
//
//   bench_node pub  COUNT QUEUE PERIOD KIND SUBSCRIBERS NAME
//   bench_node sub  COUNT QUEUE KIND WARMUP PUBLISHERS NAME   (prints "ready", then its figures)
//   bench_node ping COUNT WARMUP NAME                         (round trips through a "pong")
//   bench_node pong NAME                                      (echoes /ping on /pong)
//
// QUEUE is JSON: a number, or null (roscpp's 0, an unbounded queue). PERIOD: seconds between
// messages (0: as fast as possible; negative: bursts of 10 every -PERIOD). KIND: twist, image
// or cloud. Stamps are the wall clock (Python's time.time()), so that a rosx or rospy worker
// can read a C++ worker's stamps and the other way round.

#include <ros/ros.h>
#include <geometry_msgs/Twist.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/PointCloud2.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace {

double wall() {
  timespec now;
  clock_gettime(CLOCK_REALTIME, &now);
  return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

void pause(double seconds) {
  if (seconds > 0) {
    std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
  }
}

int queue_arg(const char* text) {
  return std::string(text) == "null" ? 0 : std::atoi(text);
}

void start(const std::string& name) {
  int argc = 1;
  char program[] = "bench_node";
  char* argv[] = {program, nullptr};
  ros::init(argc, argv, name, ros::init_options::NoSigintHandler);
}

// p50 and p99 as the Python workers take them: sorted, [n / 2] and [min(n - 1, n * 0.99)].
void print_percentiles(std::vector<double>& values, const char* prefix) {
  if (values.empty()) {
    return;
  }
  std::sort(values.begin(), values.end());
  size_t n = values.size();
  size_t top = std::min(n - 1, static_cast<size_t>(static_cast<double>(n) * 0.99));
  std::printf("%s\"p50\": %.3f, \"p99\": %.3f, \"samples\": %zu", prefix, values[n / 2] * 1e6,
              values[top] * 1e6, n);
}

// -- publisher --------------------------------------------------------------------------------

template <typename M, typename Fill>
int publish_loop(ros::NodeHandle& node, long count, int queue, double period, int subscribers,
                 M& msg, Fill fill) {
  ros::Publisher pub = node.advertise<M>("/bench", queue);
  while (static_cast<int>(pub.getNumSubscribers()) < subscribers && ros::ok()) {
    pause(0.01);
  }
  pause(0.5);
  double begin = wall();
  for (long i = 0; i < count; ++i) {
    fill(msg, i);
    pub.publish(msg);
    if (period > 0) {
      pause(period);
    } else if (period < 0 && i % 10 == 9) {
      pause(-period);
    }
  }
  std::printf("{\"pub_rate\": %.3f}\n", static_cast<double>(count) / (wall() - begin));
  std::fflush(stdout);
  pause(1.0);
  return 0;
}

int run_publisher(int argc, char** argv) {
  if (argc != 8) {
    std::fprintf(stderr, "usage: bench_node pub COUNT QUEUE PERIOD KIND SUBSCRIBERS NAME\n");
    return 2;
  }
  long count = std::atol(argv[2]);
  int queue = queue_arg(argv[3]);
  double period = std::atof(argv[4]);
  std::string kind = argv[5];
  int subscribers = std::atoi(argv[6]);
  start(argv[7]);
  ros::NodeHandle node;
  if (kind == "twist") {
    geometry_msgs::Twist msg;
    return publish_loop(node, count, queue, period, subscribers, msg,
                        [](geometry_msgs::Twist& m, long i) {
                          m.linear.x = wall();
                          m.linear.y = static_cast<double>(i);
                          if (i % 10 == 0) {
                            m.angular.x = m.linear.x;  // when the burst (of 10) began
                          }
                        });
  }
  if (kind == "image") {
    sensor_msgs::Image msg;
    msg.height = 512;
    msg.width = 512;
    msg.encoding = "rgba8";
    msg.step = 2048;
    msg.data.assign(1 << 20, 0);
    return publish_loop(node, count, queue, period, subscribers, msg,
                        [](sensor_msgs::Image& m, long i) { m.header.frame_id = std::to_string(i); });
  }
  sensor_msgs::PointCloud2 msg;
  msg.height = 1;
  msg.width = 655360;
  msg.point_step = 16;
  msg.row_step = 10485760;
  msg.data.assign(10 << 20, 0);
  return publish_loop(node, count, queue, period, subscribers, msg,
                      [](sensor_msgs::PointCloud2& m, long i) { m.header.frame_id = std::to_string(i); });
}

// -- subscriber -------------------------------------------------------------------------------

struct Received {
  long count = 0;
  long warmup = 0;
  int publishers = 1;
  std::mutex lock;
  std::condition_variable changed;
  long n = 0;
  bool done = false;
  double first = 0;
  double last = 0;
  double bytes = 0;
  std::vector<double> latencies;

  // Called by the one callback thread; `n` and `done` are read by the main thread.
  void arrived(double now, bool is_last) {
    std::lock_guard<std::mutex> guard(lock);
    if (n == 0) {
      first = now;
    }
    ++n;
    last = now;
    if (is_last || n == count * publishers) {
      done = true;
      changed.notify_all();
    }
  }
};

Received received;

void on_twist(const geometry_msgs::Twist::ConstPtr& msg) {
  double now = wall();
  if (msg->linear.y >= received.warmup) {
    received.latencies.push_back(now - msg->linear.x);
  }
  received.arrived(now, msg->linear.y == received.count - 1 && received.publishers == 1);
}

template <typename M>
void on_large(const boost::shared_ptr<const M>& msg) {
  double now = wall();
  received.bytes += static_cast<double>(msg->data.size());
  bool is_last = std::atol(msg->header.frame_id.c_str()) == received.count - 1;
  received.arrived(now, is_last && received.publishers == 1);
}

int run_subscriber(int argc, char** argv) {
  if (argc != 8) {
    std::fprintf(stderr, "usage: bench_node sub COUNT QUEUE KIND WARMUP PUBLISHERS NAME\n");
    return 2;
  }
  received.count = std::atol(argv[2]);
  int queue = queue_arg(argv[3]);
  std::string kind = argv[4];
  received.warmup = std::atol(argv[5]);
  received.publishers = std::atoi(argv[6]);
  start(argv[7]);
  ros::NodeHandle node;
  ros::Subscriber sub;
  if (kind == "twist") {
    sub = node.subscribe("/bench", queue, on_twist);
  } else if (kind == "image") {
    sub = node.subscribe("/bench", queue, on_large<sensor_msgs::Image>);
  } else {
    sub = node.subscribe("/bench", queue, on_large<sensor_msgs::PointCloud2>);
  }
  ros::AsyncSpinner spinner(1);  // the callback thread, as ros::spin() would be
  spinner.start();
  std::printf("ready\n");
  std::fflush(stdout);
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  {
    std::unique_lock<std::mutex> guard(received.lock);
    while (!received.done && std::chrono::steady_clock::now() < deadline) {
      long before = received.n;
      received.changed.wait_for(guard, std::chrono::seconds(3));
      if (received.n == before && before) {
        break;
      }
    }
  }
  spinner.stop();
  std::lock_guard<std::mutex> guard(received.lock);
  double span = std::max(received.last - received.first, 1e-9);
  std::printf("{\"received\": %ld, \"rate\": %.3f, \"bytes_rate\": %.3f", received.n,
              static_cast<double>(received.n) / span, received.bytes / span);
  print_percentiles(received.latencies, ", ");
  std::printf("}\n");
  std::fflush(stdout);
  return 0;
}

// -- ping-pong --------------------------------------------------------------------------------

struct Pinger {
  ros::Publisher pub;
  long count = 0;
  long warmup = 0;
  long sent = 0;
  std::mutex lock;
  std::condition_variable changed;
  bool done = false;
  bool answered = false;
  std::vector<double> one_way;
  geometry_msgs::Twist msg;

  void send(long index) {
    msg.linear.y = static_cast<double>(index);
    msg.linear.x = wall();
    pub.publish(msg);
  }

  // The callback thread: a round trip ended; the next ping goes out from here.
  void on_pong(const geometry_msgs::Twist::ConstPtr& echo) {
    double now = wall();
    long index = static_cast<long>(echo->linear.y);
    if (index < 0) {  // the probe that found the ponger connected
      std::lock_guard<std::mutex> guard(lock);
      answered = true;
      changed.notify_all();
      return;
    }
    if (index != sent) {
      return;  // a late answer to a probe sent twice
    }
    if (index >= warmup) {
      one_way.push_back((now - echo->linear.x) / 2);
    }
    if (index + 1 == count) {
      std::lock_guard<std::mutex> guard(lock);
      done = true;
      changed.notify_all();
      return;
    }
    sent = index + 1;
    send(sent);
  }
};

int run_ping(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: bench_node ping COUNT WARMUP NAME\n");
    return 2;
  }
  static Pinger pinger;
  pinger.count = std::atol(argv[2]);
  pinger.warmup = std::atol(argv[3]);
  start(argv[4]);
  ros::NodeHandle node;
  pinger.pub = node.advertise<geometry_msgs::Twist>("/ping", 100);
  ros::Subscriber sub = node.subscribe("/pong", 100, &Pinger::on_pong, &pinger);
  ros::AsyncSpinner spinner(1);
  spinner.start();
  // Probes (index -1) until one comes back: both connections are up.
  {
    std::unique_lock<std::mutex> guard(pinger.lock);
    auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (!pinger.answered && std::chrono::steady_clock::now() < deadline) {
      guard.unlock();
      pinger.msg.linear.y = -1;
      pinger.pub.publish(pinger.msg);
      guard.lock();
      pinger.changed.wait_for(guard, std::chrono::milliseconds(100));
    }
  }
  pause(0.5);
  pinger.send(0);
  {
    std::unique_lock<std::mutex> guard(pinger.lock);
    pinger.changed.wait_for(guard, std::chrono::seconds(120), [] { return pinger.done; });
  }
  spinner.stop();
  std::printf("{\"received\": %ld", pinger.sent + 1);
  print_percentiles(pinger.one_way, ", ");
  std::printf("}\n");
  std::fflush(stdout);
  return 0;
}

ros::Publisher pong_pub;

void on_ping(const geometry_msgs::Twist::ConstPtr& msg) {
  pong_pub.publish(msg);
}

int run_pong(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: bench_node pong NAME\n");
    return 2;
  }
  start(argv[2]);
  ros::NodeHandle node;
  pong_pub = node.advertise<geometry_msgs::Twist>("/pong", 100);
  ros::Subscriber sub = node.subscribe("/ping", 100, on_ping);
  std::printf("ready\n");
  std::fflush(stdout);
  ros::spin();  // until the bench stops it
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "pub") {
    return run_publisher(argc, argv);
  }
  if (mode == "sub") {
    return run_subscriber(argc, argv);
  }
  if (mode == "ping") {
    return run_ping(argc, argv);
  }
  if (mode == "pong") {
    return run_pong(argc, argv);
  }
  std::fprintf(stderr, "usage: bench_node pub|sub|ping|pong ...\n");
  return 2;
}
