// Where MediaStreamTrackProcessor is missing: each block of the
// microphone's first channel posted to the page, in order.
class Capture extends AudioWorkletProcessor {
  process(inputs) {
    const channel = inputs[0]?.[0];
    if (channel) this.port.postMessage(channel.slice());
    return true;
  }
}
registerProcessor("capture", Capture);
