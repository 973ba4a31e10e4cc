// roslib (npm) in node against rosx's bridge: prints one JSON line per step for the test to read.
// Usage: node roslib_client.mjs ws://127.0.0.1:PORT
import * as ROSLIB from "roslib";

const say = (step, value) => console.log(JSON.stringify({ step, value }));
const fail = (why) => {
  say("error", String(why));
  process.exit(1);
};
setTimeout(() => fail("timed out"), 30000).unref();

const ros = new ROSLIB.Ros({ url: process.argv[2] });
ros.on("error", (err) => fail(err?.message ?? err));
await new Promise((resolve) => ros.on("connection", resolve));
say("connected", true);

const topics = await new Promise((resolve, reject) => ros.getTopics(resolve, reject));
say("topics", topics.topics);

const poses = [];
const pose = new ROSLIB.Topic({ ros, name: "/turtle1/pose", messageType: "turtlesim/Pose" });
pose.subscribe((msg) => poses.push(msg));
const cmd = new ROSLIB.Topic({ ros, name: "/turtle1/cmd_vel", messageType: "geometry_msgs/Twist" });
const first = await new Promise((resolve) => {
  const wait = setInterval(() => {
    if (poses.length) {
      clearInterval(wait);
      resolve(poses[poses.length - 1]);
    }
  }, 10);
});
say("pose", first);
const moved = await new Promise((resolve) => {
  const drive = setInterval(() => {
    cmd.publish({ linear: { x: 0, y: 0, z: 0 }, angular: { x: 0, y: 0, z: 2.0 } });
    const last = poses[poses.length - 1];
    if (last.angular_velocity === 2.0) {
      clearInterval(drive);
      resolve(last);
    }
  }, 20);
});
say("turning", moved.angular_velocity);
pose.unsubscribe();

const spawn = new ROSLIB.Service({ ros, name: "/spawn", serviceType: "turtlesim/Spawn" });
const spawned = await new Promise((resolve, reject) =>
  spawn.callService({ x: 4, y: 4, theta: 0, name: "from_node" }, resolve, reject),
);
say("spawned", spawned.name);
const type = await new Promise((resolve, reject) => ros.getServiceType("/spawn", resolve, reject));
say("service_type", type);

const add = new ROSLIB.Service({ ros, name: "/roslib_add", serviceType: "rospy_tutorials/AddTwoInts" });
const called = new Promise((resolve) => {
  add.advertise((request, response) => {
    response.sum = request.a + request.b;
    resolve(request);
    return true;
  });
});
say("advertised", "/roslib_add");
say("served", await called);
setTimeout(() => {
  ros.close();
  process.exit(0);
}, 200);
