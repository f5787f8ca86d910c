// Validates a .glb with Khronos' glTF validator (npm gltf-validator, pinned beside three.js)
// and prints the report's issue counts as JSON: used by Python.TestExport.
const fs = require("fs");
const validator = require("gltf-validator");

validator
  .validateBytes(new Uint8Array(fs.readFileSync(process.argv[2])))
  .then((report) => console.log(JSON.stringify(report.issues)))
  .catch((error) => {
    console.error(error);
    process.exit(2);
  });
