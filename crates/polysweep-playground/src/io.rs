//! Files in and out, the one part that differs between the browser and a native window.
//!
//! Opening and dropping files, on the web, is asynchronous: the bytes arrive in an inbox that the app empties on its
//! next frame. Natively files are read at once. Saving downloads a file in the browser and writes into the working
//! directory natively (named in the status line), which keeps the native build free of a dialog toolkit.

use eframe::egui::{Context, DroppedFileHandle};
use std::cell::RefCell;
use std::io::Read;
use std::rc::Rc;

/// A file's name and its bytes, or why they could not be read.
pub type Incoming = (String, Result<Vec<u8>, String>);

#[derive(Clone, Default)]
pub struct Files {
    inbox: Rc<RefCell<Vec<Incoming>>>,
}

impl Files {
    /// Files that have arrived since the last call.
    pub fn take(&self) -> Vec<Incoming> {
        std::mem::take(&mut self.inbox.borrow_mut())
    }

    /// Reads a file dropped on the window.
    pub fn receive_dropped(&self, ctx: &Context, file: DroppedFileHandle) {
        let name = file.path().display().to_string();
        #[cfg(not(target_arch = "wasm32"))]
        {
            let _ = ctx;
            self.inbox.borrow_mut().push((name, file.bytes()));
        }
        #[cfg(target_arch = "wasm32")]
        {
            let (inbox, ctx) = (self.inbox.clone(), ctx.clone());
            wasm_bindgen_futures::spawn_local(async move {
                let bytes = file.bytes_async().await;
                inbox.borrow_mut().push((name, bytes));
                ctx.request_repaint();
            });
        }
    }

    /// Natively: reads the file at `path`.
    #[cfg(not(target_arch = "wasm32"))]
    pub fn open_path(&self, path: &str) {
        let bytes = std::fs::read(path).map_err(|e| e.to_string());
        self.inbox.borrow_mut().push((path.to_owned(), bytes));
    }

    /// In the browser: shows the file picker.
    #[cfg(target_arch = "wasm32")]
    pub fn open_picker(&self, ctx: &Context) {
        use wasm_bindgen::{closure::Closure, JsCast};
        let Some(document) = web_sys::window().and_then(|w| w.document()) else {
            return;
        };
        let Ok(input) = document.create_element("input") else {
            return;
        };
        let input: web_sys::HtmlInputElement = input.unchecked_into();
        input.set_type("file");
        input.set_accept(".json,.geojson,.gz,application/geo+json,application/json");
        let (inbox, ctx, chosen) = (self.inbox.clone(), ctx.clone(), input.clone());
        let on_change = Closure::once_into_js(move || {
            let Some(file) = chosen.files().and_then(|files| files.get(0)) else {
                return;
            };
            wasm_bindgen_futures::spawn_local(async move {
                let bytes = wasm_bindgen_futures::JsFuture::from(file.array_buffer())
                    .await
                    .map(|buffer| js_sys::Uint8Array::new(&buffer).to_vec())
                    .map_err(|e| format!("{e:?}"));
                inbox.borrow_mut().push((file.name(), bytes));
                ctx.request_repaint();
            });
        });
        input.set_onchange(Some(on_change.unchecked_ref()));
        input.click();
    }

    /// Saves `text` as a file called `name`; returns where it went.
    pub fn save(&self, name: &str, text: &str) -> Result<String, String> {
        #[cfg(not(target_arch = "wasm32"))]
        {
            std::fs::write(name, text).map_err(|e| format!("{name}: {e}"))?;
            let path = std::env::current_dir()
                .map(|d| d.join(name))
                .unwrap_or_else(|_| name.into());
            Ok(format!("saved {}", path.display()))
        }
        #[cfg(target_arch = "wasm32")]
        {
            download(name, text).map_err(|e| format!("{name}: {e:?}"))?;
            Ok(format!("downloaded {name}"))
        }
    }
}

#[cfg(target_arch = "wasm32")]
fn download(name: &str, text: &str) -> Result<(), wasm_bindgen::JsValue> {
    use wasm_bindgen::JsCast;
    let parts = js_sys::Array::of1(&text.into());
    let options = web_sys::BlobPropertyBag::new();
    options.set_type("application/geo+json");
    let blob = web_sys::Blob::new_with_str_sequence_and_options(&parts, &options)?;
    let url = web_sys::Url::create_object_url_with_blob(&blob)?;
    let document = web_sys::window()
        .and_then(|w| w.document())
        .ok_or("no document")?;
    let anchor: web_sys::HtmlAnchorElement = document.create_element("a")?.unchecked_into();
    anchor.set_href(&url);
    anchor.set_download(name);
    anchor.click();
    web_sys::Url::revoke_object_url(&url)
}

/// The text of a file, un-gzipping it when it starts with gzip's magic number.
pub fn text_of(bytes: &[u8]) -> Result<String, String> {
    if bytes.starts_with(&[0x1f, 0x8b]) {
        let mut text = String::new();
        flate2::read::GzDecoder::new(bytes)
            .read_to_string(&mut text)
            .map_err(|e| format!("gzip: {e}"))?;
        Ok(text)
    } else {
        String::from_utf8(bytes.to_vec()).map_err(|_| "the file is not UTF-8 text".to_owned())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Write;

    #[test]
    fn reads_plain_and_gzipped_text() {
        let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
        gz.write_all(b"{\"type\":\"Polygon\"}").unwrap();
        assert_eq!(
            text_of(&gz.finish().unwrap()).unwrap(),
            "{\"type\":\"Polygon\"}"
        );
        assert_eq!(text_of(b"[]").unwrap(), "[]");
        assert!(text_of(&[0xff, 0xfe, 0x00]).is_err());
    }
}
