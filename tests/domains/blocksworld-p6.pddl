(define (problem bw6) (:domain blocksworld)
  (:objects a b c d e f - block)
  (:init (on a b) (on b c) (ontable c) (clear a) (ontable d) (on e d) (clear e) (ontable f) (clear f) (handempty))
  (:goal (and (on c b) (on b a) (on a f) (on d e))))
