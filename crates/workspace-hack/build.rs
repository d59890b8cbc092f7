// A build script, so that the build-dependencies (host-side features)
// take part in the resolution.
fn main() {}
