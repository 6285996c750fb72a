// The handlers' one way to read a session's failure: a binding answers "" when it worked, else the
// error record {ok: false, field, message} as JSON (web/bindings/error_record.h); the reply to the
// page is {type: 'error', id, client, field, message}, so no page parses error text.
// Does not: word anything (the core's line is the message) or decide which request is current.

// The record of an answer, or null when it worked.
export function errorOf(answer) {
  if (!answer) return null;
  const record = JSON.parse(answer);
  return record && record.ok === false ? record : null;
}

// The 'error' reply of a record for request `id` of `client` (extra fields such as `control`).
export function errorReply(record, id, client, extra = {}) {
  return { type: 'error', id, client, field: record.field || '', message: record.message, ...extra };
}
