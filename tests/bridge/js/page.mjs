// The page's script (bundled with roslib by esbuild): shows the turtle's pose, live, as text.
import * as ROSLIB from "roslib";

const out = document.getElementById("pose");
const port = new URLSearchParams(location.search).get("port");
const ros = new ROSLIB.Ros({ url: `ws://127.0.0.1:${port}` });
ros.on("error", () => {
  out.textContent = "error: no connection";
});
ros.on("close", () => {
  if (!out.textContent.startsWith("x=")) out.textContent = "error: connection closed";
});
ros.on("connection", () => {
  const pose = new ROSLIB.Topic({ ros, name: "/turtle1/pose", messageType: "turtlesim/Pose" });
  pose.subscribe((msg) => {
    out.textContent = `x=${msg.x.toFixed(3)} y=${msg.y.toFixed(3)} theta=${msg.theta.toFixed(3)}`;
  });
});
