// Old URL of the worker (embeds cached before the reshape): the router is web/worker/worker.js.
import './worker/worker.js';
