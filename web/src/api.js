// The C API of klueng.wasm (src/wasm/klueng_api.cpp) as requests and answers: one request,
// one call, one answer. The worker answers the page's requests with it; a page opened from
// a file (file://, where browsers start no worker) calls it itself.
export function makeApi(M) {
  return {
    M,
    info: M.cwrap('klueng_info', 'string', ['number']),
    sample: M.cwrap('klueng_sample', 'string', ['string']),
    check: M.cwrap('klueng_check', 'string', ['string', 'string', 'number', 'number']),
    explain: M.cwrap('klueng_explain', 'string', ['string', 'number', 'string', 'number', 'number']),
    run: M.cwrap('klueng_run', 'string', ['string', 'string', 'number', 'number']),
    advance: M.cwrap('klueng_advance', 'string', ['number', 'number']),
    profile: M.cwrap('klueng_profile', 'number', []),
    profileSize: M.cwrap('klueng_profile_size', 'number', []),
    toolImage: M.cwrap('klueng_tool_image', 'string', []),
  };
}

export function handle(k, r) {
  switch (r.type) {
    case 'info':
      return JSON.parse(k.info(r.lang));
    case 'sample':
      return { text: k.sample(r.name) };
    case 'check': {
      const t0 = performance.now();
      const result = JSON.parse(k.check(r.text, r.machine, r.units, r.lang));
      result.ms = performance.now() - t0;
      return result;
    }
    case 'explain':
      return JSON.parse(k.explain(r.text, r.line, r.machine, r.units, r.lang));
    case 'run': {
      const t0 = performance.now();
      const result = JSON.parse(k.run(r.text, r.machine, r.units, r.lang));
      result.ms = performance.now() - t0;
      return result;
    }
    case 'advance': {
      const state = JSON.parse(k.advance(r.t, r.lang));
      const n = k.profileSize();
      const at = k.profile() >> 2;
      // A copy: the module's memory may grow (and move) on the next call.
      state.profile = new Float32Array(k.M.HEAPF32.subarray(at, at + n));
      return state;
    }
    case 'toolImage':
      return JSON.parse(k.toolImage());
    default:
      throw new Error(`unknown request ${r.type}`);
  }
}
