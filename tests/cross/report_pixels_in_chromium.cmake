# The report's pixel views in headless Chromium (validate/report/report_pixels.h):
# a harness page next to the report loads it in a frame and checks that
# every image decoded, that a viewer button swaps the image shown (to one
# that decodes), and that the crop of the heat map around the pair's worst
# unexplained pixel shows that one pixel bright and its neighbours dark
# (the single wrong pixel of single_pixel_validate.cmake). The harness puts
# "PIXELS OK" or "PIXELS BROKEN: why" in its title.
# -DREPORT=.../report.html -DPAIR=reference-povray
find_program(CHROMIUM chromium REQUIRED)
if(NOT EXISTS ${REPORT})
  message(FATAL_ERROR "${REPORT} does not exist")
endif()
get_filename_component(dir ${REPORT} DIRECTORY)
set(harness ${dir}/pixels_harness.html)
file(WRITE ${harness} [=[<!DOCTYPE html><html><head><meta charset="utf-8"><title>pending</title></head><body>
<iframe id="f" src="report.html" style="width:1400px;height:900px"></iframe>
<script>
function done(why) { document.title = why ? 'PIXELS BROKEN: ' + why : 'PIXELS OK'; }
function loaded(img) {
  return new Promise(function (ok) {
    if (img.complete) return ok();
    img.addEventListener('load', ok); img.addEventListener('error', ok);
  });
}
function rgb(img, x, y) {
  var c = document.createElement('canvas'); c.width = img.naturalWidth; c.height = img.naturalHeight;
  var g = c.getContext('2d'); g.drawImage(img, 0, 0);
  return g.getImageData(x, y, 1, 1).data;
}
document.getElementById('f').addEventListener('load', async function () {
  try {
    var d = this.contentDocument, imgs = Array.from(d.images);
    await Promise.all(imgs.map(loaded));
    var bad = imgs.filter(function (i) { return i.naturalWidth === 0; });
    if (bad.length) return done('not decoded: ' + bad.map(function (i) { return i.getAttribute('src'); }).join(' '));
    var v = d.querySelector('[data-viewer]');
    if (!v) return done('no viewer');
    var shown = v.querySelector('img.swap'), before = shown.getAttribute('src');
    var other = Array.from(v.querySelectorAll('button[data-src]')).filter(function (b) {
      return b.getAttribute('data-src') !== before; })[0];
    if (!other) return done('no second view to swap to');
    other.click();
    if (shown.getAttribute('src') === before) return done('the swap did not change the image');
    await new Promise(function (ok) { shown.addEventListener('load', ok); shown.addEventListener('error', ok);
                                      if (shown.complete) ok(); });
    if (shown.naturalWidth === 0) return done('the swapped-in image did not decode: ' + shown.getAttribute('src'));
    var crop = d.querySelector('.crops[data-pair="XVAL_PAIR_ID"][data-which="worst_unexplained"] img.crop.heat');
    if (!crop) return done('no heat-map crop of the worst unexplained pixel of XVAL_PAIR_ID');
    var x = +crop.getAttribute('data-x'), y = +crop.getAttribute('data-y');
    var at = rgb(crop, x, y), near = rgb(crop, x + 2, y), near2 = rgb(crop, x, y - 2);
    var bright = function (p) { return p[0] + p[1] + p[2] > 400; };
    if (!bright(at)) return done('the wrong pixel is not bright in the crop: ' + Array.from(at));
    if (bright(near) || bright(near2)) return done('its neighbours are bright too: ' + Array.from(near) + ' ' + Array.from(near2));
    if (crop.getBoundingClientRect().width < 8 * crop.naturalWidth) return done('the crop is not magnified');
    done('');
  } catch (e) { done(String(e)); }
});
</script></body></html>
]=])
file(READ ${harness} text)
string(REPLACE "XVAL_PAIR_ID" "${PAIR}" text "${text}")
file(WRITE ${harness} "${text}")
set(profile ${dir}/chromium-profile-pixels)
file(REMOVE_RECURSE ${profile})
execute_process(COMMAND ${CHROMIUM} --headless --no-sandbox --disable-gpu --disable-quic --no-first-run
                        --disable-background-networking --disable-component-update --disable-sync
                        --allow-file-access-from-files --user-data-dir=${profile} --virtual-time-budget=15000
                        --dump-dom file://${harness}
                OUTPUT_VARIABLE dom ERROR_VARIABLE err RESULT_VARIABLE rc TIMEOUT 120)
file(REMOVE_RECURSE ${profile})
string(REGEX MATCH "<title>[^<]*</title>" title "${dom}")
message(STATUS "chromium: ${title}")
if(NOT rc EQUAL 0 OR NOT title MATCHES "PIXELS OK")
  message(FATAL_ERROR "report pixel check failed (exit ${rc}): ${title}\n${err}")
endif()
