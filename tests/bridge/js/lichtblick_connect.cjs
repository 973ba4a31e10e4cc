// Lichtblick's rosbridge connect sequence with Lichtblick's own packages, in node: the topics and
// their raw definitions (asked again every 3 s), the ROS version from rosgraph_msgs/Log, cbor-raw
// subscriptions (always /clock) read with @lichtblick/rosmsg-serialization, the nodes and their
// details, the service's type before a call, and an advertisement with queue_size 0.
// Usage: node lichtblick_connect.cjs ws://127.0.0.1:PORT
globalThis.WebSocket = require("ws").WebSocket; // the browser's WebSocket, which roslibjs expects
const roslib = require("@lichtblick/roslibjs");
const { parse } = require("@lichtblick/rosmsg");
const { MessageReader } = require("@lichtblick/rosmsg-serialization");

const say = (step, value) => console.log(JSON.stringify({ step, value }));
const fail = (why) => {
  say("error", String(why));
  process.exit(1);
};
setTimeout(() => fail("timed out"), 30000).unref();
const ask = (fn, ...args) => new Promise((resolve, reject) => fn(...args, resolve, reject));

const ros = new roslib.Ros({ url: process.argv[2] });
ros.on("error", (err) => fail(err?.message ?? err));
ros.on("connection", async () => {
  try {
    const first = await ask(ros.getTopicsAndRawTypes.bind(ros));
    say("ros_version", first.types.includes("rosgraph_msgs/Log") ? 1 : 0);
    const readers = {};
    first.topics.forEach((topic, i) => {
      readers[topic] = new MessageReader(parse(first.typedefs_full_text[i], { ros2: false }));
    });
    say("topics", first.topics.length);
    for (const name of ["/clock", "/turtle1/pose"]) {
      if (!readers[name]) continue;
      const topic = new roslib.Topic({ ros, name, compression: "cbor-raw" });
      topic.subscribe((message) => {
        const decoded = readers[name].readMessage(new Uint8Array(message.bytes));
        if (name === "/turtle1/pose" && !say.posed) {
          say.posed = true;
          say("pose", decoded);
        }
      });
    }
    const nodes = await ask(ros.getNodes.bind(ros));
    const details = await Promise.all(
      nodes.map((node) =>
        new Promise((resolve, reject) =>
          ros.getNodeDetails(node, (subscriptions, publications, services) =>
            resolve({ node, subscriptions, publications, services }), reject),
        ),
      ),
    );
    say("node_details", details.find((d) => d.node === "/turtlesim"));
    const type = await ask(ros.getServiceType.bind(ros), "/spawn");
    const spawn = new roslib.Service({ ros, name: "/spawn", serviceType: type });
    const answer = await ask(spawn.callService.bind(spawn), { x: 8, y: 8, theta: 1, name: "lichtblick" });
    say("spawned", answer.name);
    const cmd = new roslib.Topic({ ros, name: "/lichtblick/cmd_vel", messageType: "geometry_msgs/Twist", queue_size: 0 });
    cmd.advertise();
    say("advertised", "/lichtblick/cmd_vel");
    setTimeout(async () => {
      const again = await ask(ros.getTopicsAndRawTypes.bind(ros));
      say("topics_again", { lichtblick: again.topics.includes("/lichtblick/pose") });
      ros.close();
      process.exit(0);
    }, 3000);
  } catch (err) {
    fail(err?.message ?? err);
  }
});
