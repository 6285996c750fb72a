// A promise that resolves in a new task of the worker's event loop, so that messages from the page
// (a newer update that supersedes a grow) run in between. Through a MessageChannel rather than
// setTimeout(0): HTML clamps timers nested five deep to at least 4 ms, and a grow that yields once a
// year paid that clamp for most of its years (issue 17 item 7).
// Does not: order itself against the worker's own messages beyond "a later task".
const channel = new MessageChannel();
const waiting = [];
channel.port1.onmessage = () => waiting.shift()();

export function nextTask() {
  return new Promise((resolve) => {
    waiting.push(resolve);
    channel.port2.postMessage(0);
  });
}
