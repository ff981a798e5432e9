// The JavaScript face of isoparm_geom (geom_entry.cpp), appended to the module (--post-js):
//
//   const geom = await IsoparmGeom();              // isoparm-geom.js
//   geom.request('{"op":"basis",...}')             // the response text, as `isoparm geom` prints it
//   geom.requestJSON({op: "basis", ...})           // the same, parsed (an array answers a batch)
//
// A text that is not JSON throws an Error with the command line's message (its exit status 2);
// a request the protocol refuses is an ordinary answer, {"ok": false, "error": {...}}.
Module['request'] = function (text) {
  text = String(text);
  const size = lengthBytesUTF8(text) + 1;
  const input = _malloc(size);
  const status = _malloc(4);
  try {
    stringToUTF8(text, input, size);
    const answer = UTF8ToString(_isoparm_geom(input, status));
    if (HEAP32[status >> 2] === 2) throw new Error(answer.trim());
    return answer;
  } finally {
    _free(input);
    _free(status);
  }
};

Module['requestJSON'] = function (request) {
  return JSON.parse(Module['request'](JSON.stringify(request)));
};
