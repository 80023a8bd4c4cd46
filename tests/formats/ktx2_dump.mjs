// Prints what an independent KTX 2.0 parser (the npm package ktx-parse,
// by Don McCurdy, not lutbake's) reads from a .ktx2 file, as one JSON
// object: the header, the data format descriptor, the key/value data (as
// text) and level 0's texels decoded from R16/R32 (G16/G32) SFLOAT.
// Usage: node ktx2_dump.mjs <node_modules dir holding ktx-parse> <file.ktx2>
import { readFileSync } from 'node:fs';
import { pathToFileURL } from 'node:url';
import { join } from 'node:path';

const [modules, file] = process.argv.slice(2);
const { read } = await import(pathToFileURL(join(modules, 'ktx-parse', 'dist', 'index.mjs')).href);
const container = read(new Uint8Array(readFileSync(file)));

function halfToNumber(bits) {
  const sign = bits & 0x8000 ? -1 : 1;
  const exponent = (bits >> 10) & 0x1f;
  const mantissa = bits & 0x3ff;
  if (exponent === 0) return sign * mantissa * 2 ** -24;
  if (exponent === 31) return mantissa ? NaN : sign * Infinity;
  return sign * (1 + mantissa / 1024) * 2 ** (exponent - 15);
}

const level = container.levels[0];
const data = level.levelData;
const view = new DataView(data.buffer, data.byteOffset, data.byteLength);
const values = [];
for (let at = 0; at < data.byteLength; at += container.typeSize)
  values.push(container.typeSize === 2 ? halfToNumber(view.getUint16(at, true)) : view.getFloat32(at, true));

const keyValue = {};
for (const [key, value] of Object.entries(container.keyValue)) {
  const text = typeof value === 'string' ? value : new TextDecoder().decode(value);
  keyValue[key] = text.endsWith('\0') ? text.slice(0, -1) : text;
}
const dfd = container.dataFormatDescriptor[0];
console.log(JSON.stringify({
  vkFormat: container.vkFormat, typeSize: container.typeSize,
  pixelWidth: container.pixelWidth, pixelHeight: container.pixelHeight, pixelDepth: container.pixelDepth,
  layerCount: container.layerCount, faceCount: container.faceCount, levelCount: container.levelCount,
  supercompressionScheme: container.supercompressionScheme,
  dfd: {
    vendorId: dfd.vendorId, descriptorType: dfd.descriptorType, versionNumber: dfd.versionNumber,
    colorModel: dfd.colorModel, colorPrimaries: dfd.colorPrimaries, transferFunction: dfd.transferFunction,
    flags: dfd.flags, texelBlockDimension: dfd.texelBlockDimension, bytesPlane: dfd.bytesPlane,
    samples: dfd.samples.map((s) => ({ bitOffset: s.bitOffset, bitLength: s.bitLength, channelType: s.channelType,
      samplePosition: s.samplePosition, sampleLower: s.sampleLower >>> 0, sampleUpper: s.sampleUpper >>> 0 })),
  },
  keyValue,
  levelByteLength: data.byteLength, uncompressedByteLength: level.uncompressedByteLength,
  values,
}));
