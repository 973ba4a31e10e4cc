// What `ws` is in the page: the browser's own WebSocket (roslib imports `ws` only under node).
export const WebSocket = globalThis.WebSocket;
export default WebSocket;
