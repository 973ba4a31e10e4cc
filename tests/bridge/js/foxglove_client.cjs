// Foxglove's own WebSocket client (@foxglove/ws-protocol, as Foxglove Studio and Lichtblick
// use it) against rosx's Foxglove server, with Lichtblick's ROS 1 message readers and writers:
// the turtle's pose, driving it, /spawn, a parameter. One JSON line per step.
// Usage: node foxglove_client.cjs ws://127.0.0.1:PORT
const { FoxgloveClient } = require("@foxglove/ws-protocol");
const { WebSocket } = require("ws");
const { parse } = require("@lichtblick/rosmsg");
const { MessageReader, MessageWriter } = require("@lichtblick/rosmsg-serialization");

const say = (step, value) => console.log(JSON.stringify({ step, value }));
const fail = (why) => {
  say("error", String(why));
  process.exit(1);
};
setTimeout(() => fail("timed out"), 30000).unref();

const client = new FoxgloveClient({
  ws: new WebSocket(process.argv[2], [FoxgloveClient.SUPPORTED_SUBPROTOCOL]),
});
client.on("error", (err) => fail(err?.message ?? err));
client.on("status", (status) => say("status", status.message));
client.on("serverInfo", (info) => say("capabilities", info.capabilities));

let poseReader;
let cmdChannel;
let twist;
const poseSubs = new Set();
client.on("advertise", (channels) => {
  const pose = channels.find((c) => c.topic === "/turtle1/pose");
  if (!pose || poseReader) return;
  say("schema", { encoding: pose.encoding, schemaName: pose.schemaName });
  poseReader = new MessageReader(parse(pose.schema, { ros2: false }));
  poseSubs.add(client.subscribe(pose.id));
  const twistSchema = channels.find((c) => c.schemaName === "geometry_msgs/Twist");
  twist = new MessageWriter(parse(twistSchema.schema, { ros2: false }));
  cmdChannel = client.advertise({ topic: "/turtle1/cmd_vel", encoding: "ros1", schemaName: "geometry_msgs/Twist" });
});

let turned = false;
client.on("message", ({ subscriptionId, data }) => {
  if (!poseSubs.has(subscriptionId)) return;
  const pose = poseReader.readMessage(new Uint8Array(data.buffer, data.byteOffset, data.byteLength));
  if (!turned) {
    if (pose.angular_velocity === 1.5) {
      turned = true;
      say("turning", pose.angular_velocity);
    } else {
      client.sendMessage(cmdChannel, twist.writeMessage({ linear: { x: 0, y: 0, z: 0 }, angular: { x: 0, y: 0, z: 1.5 } }));
    }
  }
});

let spawnAsked = false;
client.on("advertiseServices", (services) => {
  const spawn = services.find((s) => s.name === "/spawn");
  if (!spawn || spawnAsked) return;
  spawnAsked = true;
  const request = new MessageWriter(parse(spawn.request.schema, { ros2: false }));
  const response = new MessageReader(parse(spawn.response.schema, { ros2: false }));
  client.on("serviceCallResponse", ({ callId, data }) => {
    const answer = response.readMessage(new Uint8Array(data.buffer, data.byteOffset, data.byteLength));
    say("spawned", { callId, name: answer.name });
    client.getParameters(["/turtlesim/background_b"], "p");
  });
  client.sendServiceCallRequest({
    serviceId: spawn.id,
    callId: 7,
    encoding: "ros1",
    data: new DataView(request.writeMessage({ x: 2, y: 2, theta: 0, name: "foxglove" }).buffer),
  });
});

client.on("parameterValues", ({ parameters, id }) => {
  say("parameters", { id, parameters });
  const wait = setInterval(() => {
    if (turned) {
      clearInterval(wait);
      client.close();
      process.exit(0);
    }
  }, 20);
});
