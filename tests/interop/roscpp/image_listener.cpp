// A roscpp subscriber of sensor_msgs/Image for the interop tests (compiled by the tests with
// bench/roscpp_program.py's build, skipped without Debian's libroscpp-dev).
//
//   image_listener TOPIC QUEUE DELAY_MS
//
// Prints "ready" once subscribed, then one line per message: its frame_id, the size of its
// data and a CRC-32 of the data, in hexadecimal; each callback then sleeps DELAY_MS (a
// slow subscriber). Runs until killed. The hash is CRC-32 (zlib's), so a test computes it with
// zlib.crc32.

#include <ros/ros.h>
#include <sensor_msgs/Image.h>

#include <chrono>
#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <thread>

namespace {

int delay_ms = 0;

std::uint32_t crc32(const std::vector<std::uint8_t>& data) {
  static std::uint32_t table[256];
  static bool made = false;
  if (!made) {
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) {
        c = (c & 1) ? 0xEDB88320U ^ (c >> 1) : c >> 1;
      }
      table[n] = c;
    }
    made = true;
  }
  std::uint32_t crc = 0xFFFFFFFFU;
  for (std::uint8_t byte : data) {
    crc = table[(crc ^ byte) & 0xFF] ^ (crc >> 8);
  }
  return crc ^ 0xFFFFFFFFU;
}

void on_image(const sensor_msgs::Image::ConstPtr& msg) {
  std::printf("%s %zu %08" PRIx32 "\n", msg->header.frame_id.c_str(), msg->data.size(),
              crc32(msg->data));
  std::fflush(stdout);
  if (delay_ms > 0) {
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: image_listener TOPIC QUEUE DELAY_MS\n");
    return 2;
  }
  int queue = std::atoi(argv[2]);
  delay_ms = std::atoi(argv[3]);
  int ros_argc = 1;
  ros::init(ros_argc, argv, "image_listener", ros::init_options::NoSigintHandler);
  ros::NodeHandle node;
  ros::Subscriber sub = node.subscribe(argv[1], queue, on_image);
  std::printf("ready\n");
  std::fflush(stdout);
  ros::spin();
  return 0;
}
