// The page is served by `geovis view` from byte arrays in the binary (cmake/build_viewer_page.cmake):
// everything is bundled, nothing comes from a CDN, and the file names carry content hashes.
import { defineConfig } from 'vite';

export default defineConfig({
  base: '/',
  build: {
    target: 'es2020',
    chunkSizeWarningLimit: 1000,
    assetsInlineLimit: 0,
    modulePreload: { polyfill: false },
  },
});
