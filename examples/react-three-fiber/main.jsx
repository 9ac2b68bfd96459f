// The Ocean in a react-three-fiber scene: one <primitive object={ocean} />, updated every frame
// in useFrame with the camera (the local waves follow it) and disposed when the component unmounts.
// JSX through vite's own transform: no React plugin is needed to build it.
import { useEffect, useState } from 'react';
import { createRoot } from 'react-dom/client';
import { Canvas, useFrame, useThree } from '@react-three/fiber';
import { Ocean } from 'three-fft-ocean';

function Sea({ options }) {
  const gl = useThree((state) => state.gl);
  const [ocean, setOcean] = useState(null);

  // Made in an effect, not in render: React may render twice (StrictMode) or throw a render away,
  // and each Ocean holds GPU resources that only dispose() frees.
  useEffect(() => {
    const made = new Ocean(gl, options); // options are read once; later: ocean.setParameters(…)
    setOcean(made);
    return () => made.dispose();
  }, [gl]); // a new Ocean only for a new renderer

  useFrame(({ clock, camera }) => {
    if (!ocean) return;
    ocean.update(clock.elapsedTime, camera); // the camera: where the local waves' grid follows
    camera.far = ocean.horizonDistanceFor(camera.position.y); // out to the horizon
    camera.updateProjectionMatrix();
  });

  return ocean ? <primitive object={ocean} /> : null;
}

function App() {
  return (
    <Canvas
      // r3f's defaults are what the sea is made for: ACES filmic tone mapping and sRGB output.
      camera={{ fov: 55, near: 0.5, far: 1e4, position: [0, 12, 0] }} // 12 m above the mean sea level
      onCreated={({ camera }) => camera.lookAt(60, 0, -80)} // the app's first view: 53° left of +x, 6.8° down
    >
      <Sea options={{ windSpeed: 12, seed: 7 }} />
    </Canvas>
  );
}

createRoot(document.getElementById('root')).render(<App />);
