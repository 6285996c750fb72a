// One request in flight at a time, the newest one wanted sent once the answer comes: how the tree
// page's view (web/tree/tree_view.js) and <niwa-tree> (public/niwa-embed.js) ask the growth worker
// for a hybrid draw list (and a motion list) while the camera moves, so the worker never builds a
// backlog of lists for cameras already left behind. Does not: send anything itself (the caller's
// `send` does, with the camera of the moment), time out, or read the answer.
export class LatestRequest {
  // send(): posts the request (called at once, or after the answer to the one in flight).
  constructor(send) {
    this.send = send;
    this.inFlight = false;
    this.wanted = false;  // asked for while one was in flight
  }

  // Sends now, or marks it wanted while a request is in flight.
  request() {
    if (this.inFlight) {
      this.wanted = true;
      return;
    }
    this.inFlight = true;
    this.wanted = false;
    this.send();
  }

  // The request in flight was answered, or will never be (dropped, a new tree): the next may go.
  // The caller sends the wanted one (request()) once the answer is used.
  done() {
    this.inFlight = false;
  }
}
