#!/bin/bash
# The Debian package end to end: builds it with CPack from the build tree into a temporary
# directory, checks what it holds (the executables, the desktop files, the icons, the man page,
# the completion) and its dependencies, runs the validators (desktop-file-validate,
# appstreamcli, lintian; each skipped with a reason only where it is not installed), and runs the
# installed tree: its aniso renders a built-in mesh and writes a thumbnail of the requested size,
# its window opens a session file given as its argument, its completion completes, its MIME
# types compile.
# Usage: test_package.sh BUILD_DIR (an X display in DISPLAY for the renders).
set -u
build=$(cd "$1" && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/aniso-package-XXXXXX")
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
skip() { echo "SKIPPED: $*"; }

# The package.
if ! (cd "$build" && cpack -G DEB -B "$tmp/out" >"$tmp/cpack.log" 2>&1); then
  cat "$tmp/cpack.log"
  echo "FAIL: cpack could not build the package"
  exit 1
fi
deb=$(ls "$tmp"/out/aniso_*.deb 2>/dev/null | head -n 1)
[ -n "$deb" ] || { echo "FAIL: cpack wrote no aniso_*.deb"; exit 1; }
echo "package: $(basename "$deb")"

# Its contents.
dpkg-deb -c "$deb" | awk '{print $NF}' | sed 's|^\./|/|' >"$tmp/contents"
expected=(
  /usr/bin/aniso
  /usr/libexec/aniso/aniso-mesh-reader
  /usr/libexec/aniso/aniso-image-io.so
  /usr/share/applications/org.aniso.Aniso.desktop
  /usr/share/metainfo/org.aniso.Aniso.metainfo.xml
  /usr/share/mime/packages/org.aniso.Aniso.xml
  /usr/share/thumbnailers/aniso.thumbnailer
  /usr/share/icons/hicolor/scalable/apps/aniso.svg
  /usr/share/man/man1/aniso.1.gz
  /usr/share/bash-completion/completions/aniso
  /usr/share/doc/aniso/copyright
  /usr/share/doc/aniso/changelog.gz
  /usr/share/doc/aniso/README.md
)
for size in 16 24 32 48 64 128 256; do
  expected+=("/usr/share/icons/hicolor/${size}x${size}/apps/aniso.png")
done
for path in "${expected[@]}"; do
  grep -qx "$path" "$tmp/contents" || fail "the package lacks $path"
done

# Its dependencies: the libraries the executables link, found by dpkg-shlibdeps.
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
for lib in libc6 libstdc++6 libvtk9.1 libqt5widgets5 libopenimageio2.4 libocct-data-exchange-7.6; do
  [[ "$depends" == *"$lib"* ]] || fail "Depends lacks $lib"
done

dpkg-deb -x "$deb" "$tmp/root"
root="$tmp/root"

# Validators.
if command -v desktop-file-validate >/dev/null; then
  desktop-file-validate "$root/usr/share/applications/org.aniso.Aniso.desktop" \
    || fail "desktop-file-validate rejects the desktop entry"
else
  skip "desktop-file-validate (desktop-file-utils) is not installed"
fi
if command -v appstreamcli >/dev/null; then
  appstreamcli validate --no-net "$root/usr/share/metainfo/org.aniso.Aniso.metainfo.xml" \
    || fail "appstreamcli rejects the metainfo"
else
  skip "appstreamcli (appstream) is not installed"
fi
if command -v lintian >/dev/null; then
  # The package's maintainer address is a build setting (ANISO_PACKAGE_MAINTAINER); the
  # default one is on localhost, which lintian rightly calls an error for a published package:
  # those two tags are left out here, every other error fails.
  lintian --tag-display-limit 0 --suppress-tags bogus-mail-host,bogus-mail-host-in-debian-changelog "$deb" \
    >"$tmp/lintian" 2>&1
  cat "$tmp/lintian"
  if grep -q '^E:' "$tmp/lintian"; then
    fail "lintian reports errors"
  fi
else
  skip "lintian is not installed"
fi

# The MIME types compile, and give the formats shared-mime-info lacks their globs.
if command -v update-mime-database >/dev/null; then
  cp -r "$root/usr/share/mime" "$tmp/mime"
  XDG_DATA_DIRS="$tmp" update-mime-database "$tmp/mime" 2>"$tmp/mime.log" || fail "update-mime-database fails"
  if [ -s "$tmp/mime.log" ]; then cat "$tmp/mime.log"; fail "update-mime-database warns"; fi
  for glob in 'model/step:\*.step' 'application/vnd.ply:\*.ply' 'application/vnd.vtp:\*.vtp' 'application/vnd.vtu:\*.vtu'; do
    grep -q "$glob" "$tmp/mime/globs2" || fail "the MIME database lacks $glob"
  done
  # A session is told from other JSON by its content (magic), a STEP file by its name.
  system_types=/usr/share/mime/packages/freedesktop.org.xml
  if command -v gio >/dev/null && [ -f "$system_types" ]; then
    cp "$system_types" "$tmp/mime/packages/"
    XDG_DATA_DIRS="$tmp" update-mime-database "$tmp/mime"
    printf '{\n    "assets": {\n    },\n    "format": "aniso-session",\n    "version": 1\n}\n' >"$tmp/s.json"
    printf '{"format": "other"}\n' >"$tmp/other.json"
    printf 'ISO-10303-21;\nHEADER;\n' >"$tmp/part.step"
    for pair in s.json=application/x-aniso-session other.json=application/json part.step=model/step; do
      type=$(XDG_DATA_DIRS="$tmp" XDG_DATA_HOME="$tmp/none" gio info -a standard::content-type \
        "$tmp/${pair%%=*}" | sed -n 's/.*content-type: //p')
      [ "$type" == "${pair#*=}" ] || fail "${pair%%=*} is of type '$type', not ${pair#*=}"
    done
  else
    skip "gio (libglib2.0-bin) or shared-mime-info's types are not installed: no content check"
  fi
else
  skip "update-mime-database (shared-mime-info) is not installed"
fi

# The man page names every command.
for command in bake render thumbnail bench; do
  zcat "$root/usr/share/man/man1/aniso.1.gz" | grep -q "^\.SH \"COMMAND ${command^^}\"" \
    || fail "the man page has no section for $command"
done

# The completion completes a command, an option of render, the window's options after a mesh
# and the values of --reference-view.
completion="$root/usr/share/bash-completion/completions/aniso"
replies=$(bash -c 'source "$1"; COMP_WORDS=(aniso thu); COMP_CWORD=1; _aniso; echo "${COMPREPLY[*]}";
  COMP_WORDS=(aniso render --export-g); COMP_CWORD=2; _aniso; echo "${COMPREPLY[*]}";
  COMP_WORDS=(aniso part.obj --ref); COMP_CWORD=2; _aniso; echo "${COMPREPLY[*]}";
  COMP_WORDS=(aniso part.obj --reference-view e); COMP_CWORD=3; _aniso; echo "${COMPREPLY[*]}"' _ "$completion")
[ "$replies" == $'thumbnail\n--export-gltf\n--reference-view\nerror' ] || fail "the completion replies '$replies'"

# The installed tree runs: a render and a thumbnail by the installed executable, which finds the
# installed reader program (../libexec/aniso from bin/).
export XDG_CACHE_HOME="$tmp/cache"
if [ -z "${DISPLAY:-}" ]; then
  fail "no X display for the renders (run under xvfb-run)"
else
  "$root/usr/bin/aniso" render --builtin torus --size 64x64 --frames 1 --samples 4 \
    -o "$tmp/render.png" >"$tmp/render.log" 2>&1 || { cat "$tmp/render.log"; fail "the installed aniso does not render"; }
  [ -s "$tmp/render.png" ] || fail "the installed aniso wrote no render"
  # An OBJ file: VTK's reader runs in the reader program (an STL would be read in-process).
  printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0.5\nf 1 2 3\nf 2 4 3\n' >"$tmp/t.obj"
  "$root/usr/bin/aniso" thumbnail "$tmp/t.obj" "$tmp/thumb" 48 >"$tmp/thumb.log" 2>&1 \
    || { cat "$tmp/thumb.log"; fail "the installed aniso writes no thumbnail"; }
  # The PNG's IHDR: width and height as 4-byte big-endian numbers at bytes 16 and 20.
  header=$(od -An -tx1 -j0 -N24 "$tmp/thumb" | tr -d ' \n')
  [ "${header:0:16}" == "89504e470d0a1a0a" ] || fail "the thumbnail is not a PNG ($header)"
  [ "$((16#${header:32:8}))x$((16#${header:40:8}))" == "48x48" ] \
    || fail "the thumbnail is $((16#${header:32:8}))x$((16#${header:40:8})), not 48x48"
  # A textured glTF: the installed reader program loads its image module (aniso-image-io.so,
  # beside it in libexec/aniso) for the texture, which is then no warning of a left-out texture.
  # The buffer: a triangle's positions and texture coordinates as little-endian floats.
  printf '\0\0\0\0\0\0\0\0\0\0\0\0\0\0\200\77\0\0\0\0\0\0\0\0\0\0\0\0\0\0\200\77\0\0\0\0\0\0\0\0\0\0\0\0\0\0\200\77\0\0\0\0\0\0\0\0\0\0\200\77' >"$tmp/t.bin"
  cp "$root/usr/share/icons/hicolor/16x16/apps/aniso.png" "$tmp/t.png"
  printf '{"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],%s%s%s%s\n' \
    '"meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1},"material":0}]}],' \
    '"materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}}],"textures":[{"source":0}],' \
    '"images":[{"uri":"t.png"}],"buffers":[{"byteLength":60,"uri":"t.bin"}],"bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":24}],' \
    '"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},{"bufferView":1,"componentType":5126,"count":3,"type":"VEC2"}]}' \
    >"$tmp/t.gltf"
  "$root/usr/bin/aniso" render "$tmp/t.gltf" --size 32x32 --frames 1 --samples 1 \
    -o "$tmp/gltf.png" >"$tmp/gltf.log" 2>&1 || { cat "$tmp/gltf.log"; fail "the installed aniso does not render a glTF"; }
  grep -q "baseColorTexture tints" "$tmp/gltf.log" || { cat "$tmp/gltf.log"; fail "the glTF's texture was not read"; }
  if grep -q "does not decode" "$tmp/gltf.log"; then
    cat "$tmp/gltf.log"; fail "the installed reader program could not decode the glTF's texture"
  fi
  # The window of the installed tree opens a session file given as its argument (the desktop
  # entry's `aniso %F`): a session naming a missing mesh fails naming that mesh, where a mesh
  # argument would have failed on the .json file itself.
  printf '{"format": "aniso-session", "version": 1, "assets": {"mesh": "%s"}}\n' \
    "$tmp/missing.stl" >"$tmp/session.json"
  XDG_CONFIG_HOME="$tmp/config" "$root/usr/bin/aniso" "$tmp/session.json" \
    --screenshot "$tmp/window.png" --quit >"$tmp/window.log" 2>&1
  code=$?
  grep -q "aniso: $tmp/session.json: $tmp/missing.stl: no such file" "$tmp/window.log" && [ "$code" -eq 1 ] \
    || { cat "$tmp/window.log"; fail "the installed window did not open the session (exit $code)"; }
fi

if [ "$failures" -gt 0 ]; then
  echo "$failures check(s) failed"
  exit 1
fi
echo "the package passed every check"
